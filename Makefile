# littermap: the two commands of the quick start, and a few more.
#   make demo    install missing packages, build, run the pipeline on the sample
#   make test    install missing packages, build, run the whole test suite
#   make check   build, run the unit tier only (no data sets, no littermap binary): under a minute
#   make bench   build and run the benchmarks (pinned to one core)
#   make sanitize-test   the unit and data tiers again under AddressSanitizer + UndefinedBehaviorSanitizer
#   make fuzz    build the libFuzzer targets with clang and run each for FUZZ_SECONDS

BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 30
# Whole-log SLAM runs: minutes at -O1 under the sanitizers for no code that the shorter real-log
# tests leave unchecked there (the release suite runs them). The tests that match features on the
# real TUM frames (the RGB-D tracker, the aligner on the TUM pair, visual odometry) pass under
# ASan, but LeakSanitizer then crashes at exit scanning the dynamic TLS that GDAL (loaded by
# OpenCV's image codecs) leaves behind ("Tracer caught signal 11"), whatever the tests do.
SANITIZE_EXCLUDE ?= WholeLog|ScanAlignmentBringsTheIntelLab|RgbdTrackerTest|TumPair|TumDesk|reconstruct\.VisualOdometry\.
JOBS ?= $(shell nproc)
DEMO_OUT ?= out/demo
CMAKE_FLAGS ?=
MAKEFLAGS += --no-print-directory
# New build folders use Ninja, which keeps both cores compiling while a library links (the
# Makefile generator waits for a library before compiling what uses it); a folder configured
# earlier keeps its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

.PHONY: all deps build demo test check bench sanitize-test fuzz clean

all: build

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD_DIR) $(call generator,$(BUILD_DIR)) -DCMAKE_BUILD_TYPE=Release \
	  $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@scripts/demo.sh $(BUILD_DIR)/cli/littermap $(DEMO_OUT)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

check: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -L unit

bench: build
	@scripts/bench.sh $(BUILD_DIR)

sanitize-test:
	@scripts/install-deps.sh --ci
	@cmake -S . -B $(SANITIZE_DIR) $(call generator,$(SANITIZE_DIR)) -DCMAKE_BUILD_TYPE=Sanitize \
	  -DLITTERMAP_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(SANITIZE_DIR) -j $(JOBS) --target littermap_tests_unit littermap_tests_data
	@cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp \
	  ctest --output-on-failure -j $(JOBS) -L 'unit|data' -E '$(SANITIZE_EXCLUDE)'

fuzz:
	@scripts/install-deps.sh --ci
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) $(call generator,$(FUZZ_DIR)) -DLITTERMAP_BUILD_FUZZ=ON \
	  -DLITTERMAP_BUILD_TESTS=OFF -DLITTERMAP_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(FUZZ_DIR) -j $(JOBS) --target littermap_fuzzers
	@scripts/fuzz.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR) out

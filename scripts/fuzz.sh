#!/usr/bin/env bash
# Runs each libFuzzer target for a while, starting from its seed corpus in fuzz/corpus/NAME, as
# many at once as there are cores (each fuzzer uses one).
#   scripts/fuzz.sh FUZZ_BUILD_DIR SECONDS
set -euo pipefail
build=$1
seconds=$2
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

run() {
  local fuzzer=$1 name corpus seeds
  name=$(basename "$fuzzer")
  corpus="$work/$name"
  mkdir -p "$corpus"
  seeds="$here/fuzz/corpus/${name#fuzz_}"
  [[ -d "$seeds" ]] && cp -r "$seeds"/. "$corpus"/
  # libFuzzer exits non-zero on a crash, which fails this target and so the run.
  # A target's scratch files go in the work folder too, whatever becomes of the fuzzer.
  if TMPDIR="$work" "$fuzzer" -max_total_time="$seconds" -print_final_stats=1 "$corpus" >"$work/$name.log" 2>&1; then
    echo "== $name for ${seconds}s: clean"
    tail -n 8 "$work/$name.log"
  else
    echo "== $name for ${seconds}s: FAILED"
    tail -n 60 "$work/$name.log"
    return 1
  fi
}

pids=()
failed=0
for fuzzer in "$build"/fuzz/fuzz_*; do
  [[ -x "$fuzzer" && -f "$fuzzer" ]] || continue
  run "$fuzzer" &
  pids+=($!)
  if (( ${#pids[@]} >= jobs )); then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit "$failed"

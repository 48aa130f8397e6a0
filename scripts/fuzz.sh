#!/usr/bin/env bash
# Runs each libFuzzer target for a while, starting from its seed corpus in fuzz/corpus/NAME.
#   scripts/fuzz.sh FUZZ_BUILD_DIR SECONDS
set -euo pipefail
build=$1
seconds=$2
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for fuzzer in "$build"/fuzz/fuzz_*; do
  [[ -x "$fuzzer" && -f "$fuzzer" ]] || continue
  name=$(basename "$fuzzer")
  corpus="$work/$name"
  mkdir -p "$corpus"
  seeds="$here/fuzz/corpus/${name#fuzz_}"
  [[ -d "$seeds" ]] && cp -r "$seeds"/. "$corpus"/
  echo "== $name for ${seconds}s"
  "$fuzzer" -max_total_time="$seconds" -print_final_stats=1 "$corpus" 2>&1 | tail -n 12
  # libFuzzer exits non-zero on a crash; set -e stops the run and CI fails.
done

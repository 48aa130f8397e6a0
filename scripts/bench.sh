#!/usr/bin/env bash
# Runs every benchmark binary pinned to one core and prints its table.
#   scripts/bench.sh BUILD_DIR
set -euo pipefail
build=$1
pin=()
if command -v taskset >/dev/null; then pin=(taskset -c 0); fi
for bench in "$build"/bench/*_bench; do
  echo "== $(basename "$bench")"
  "${pin[@]}" "$bench" --benchmark_counters_tabular=true
done

#!/usr/bin/env bash
# Runs every benchmark binary pinned to one core and prints its table; capture_bench, which
# measures the recorder's threads working together, runs on all cores.
#   scripts/bench.sh BUILD_DIR
set -euo pipefail
build=$1
# shellcheck source=bench/common.sh
source "$(dirname "$0")/../bench/common.sh"
for bench in "$build"/bench/*_bench; do
  echo "== $(basename "$bench")"
  if [[ $(basename "$bench") == capture_bench ]]; then
    "$bench" --benchmark_counters_tabular=true
  else
    "${pin[@]}" "$bench" --benchmark_counters_tabular=true
  fi
done

#!/usr/bin/env bash
# Runs every benchmark binary pinned to one core and prints its table; capture_bench, which
# measures the recorder's threads working together, and site_concurrency_bench, which measures
# processes writing one site at once, run on all cores; the site benches get the PostGIS server
# of the tests (BUILD_DIR/postgis), started for them and deleted after.
#   scripts/bench.sh BUILD_DIR
set -euo pipefail
build=$1
# shellcheck source=bench/common.sh
source "$(dirname "$0")/../bench/common.sh"
for bench in "$build"/bench/*_bench; do
  echo "== $(basename "$bench")"
  if [[ $(basename "$bench") == capture_bench ]]; then
    "$bench" --benchmark_counters_tabular=true
  elif [[ $(basename "$bench") == site_*_bench ]]; then
    url=$("$(dirname "$0")/postgis.sh" start "$build/postgis")
    if [[ $(basename "$bench") == site_scale_bench ]]; then
      "${pin[@]}" "$bench" --postgis "$url"
    else
      "$bench" --postgis "$url"
    fi
    "$(dirname "$0")/postgis.sh" destroy "$build/postgis"
  else
    "${pin[@]}" "$bench" --benchmark_counters_tabular=true
  fi
done

#!/usr/bin/env bash
# SLAM speed, memory and accuracy benchmark on the simulated parks: each world simulated once
# (cached in WORK_DIR; park_large takes about 12 minutes), then reconstructed with the hybrid
# laser + RGB-D tracker and with the laser alone, pinned to one core. Prints one row per run x
# mode: scans, run time, scans/s, peak resident memory of the whole process, ATE and RPE against
# the truth, and map_vs_truth: the 5 cm cells the scans occupy when drawn with the trajectory,
# over those with the true poses (`littermap eval map`). Runs longer than a few minutes
# (park_large) also get a per-minute table (bench/trajectory_minutes.py): error percentiles and
# distance ratio against time, so a bounded drift shows apart from a growing one. loops: the dense
# loop closer's accepted loops; lm_lps: the loops closed on landmark constellations; cam_lps: the
# RGB-D loops (hybrid only).
#   bench/slam_park.sh [LITTERMAP] [WORK_DIR] [RUN...]
# RUN is a world (park_small, park_large, ...) as shipped, or WORLD:SEED for the same world and
# route with another draw of sensor noise, odometry drift and timing (`simulate --run-seed`),
# WORLD@SEED for another park drawn from the same world file (`simulate --seed`: trees, litter,
# terrain and the run's noise), and WORLD/ROUTE or WORLD/ROUTE:SEED drives another of the world's
# `routes` (`simulate --route`), e.g. park_large/perimeter:2. The small parks' acceptance set,
# three draws and three other parks of each:
#   bench/slam_park.sh BIN DIR park_{small,tilts}:{1,2,3} park_{small,tilts}@{101,102,103}
# odom_ATE is the ATE of the run's odometry (gyro-turned where there is an IMU), the bar below
# every run's.
# One run of a park is one draw: its ATE can differ by a factor of two from the next draw's, so
# the default measures park_small over four draws and ends with each world's spread per mode.
# A benchmark, not a test: it prints, it does not assert.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=bench/common.sh
source "$here/bench/common.sh"
park_bench_arguments "$@"
if [[ ${#run_names[@]} -eq 0 ]]; then
  run_names=(park_small park_small:1 park_small:2 park_small:3 park_large)
fi
mkdir -p "$work"

# run_measured OUT_JSON COMMAND...: runs the command, writes its wall time and peak RSS.
run_measured() {
  python3 - "$@" <<'EOF'
import json, resource, subprocess, sys, time
out, command = sys.argv[1], sys.argv[2:]
start = time.monotonic()
subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
wall_s = time.monotonic() - start
peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # kibibytes on Linux
json.dump({"wall_s": wall_s, "peak_mib": peak_kib / 1024}, open(out, "w"))
EOF
}

printf '%-22s %-7s %7s %8s %8s %8s %8s %8s %8s %6s %6s %7s %12s\n' run mode scans time_s \
  scans/s peak_MiB ATE_m odom_ATE RPE_tr_m loops lm_lps cam_lps map_vs_truth
rows=$work/rows.tsv
: >"$rows"
for run_name in "${run_names[@]}"; do
  # WORLD or WORLD/ROUTE: the spread below is over its draws and parks.
  world=${run_name%%[:@]*}
  run_dir=$(simulate_park_run "$littermap" "$work" "$run_name")
  bag=$run_dir/bag
  truth=$run_dir/truth
  for mode in hybrid laser; do
    run=$run_dir/run-$mode
    flags=()
    if [[ $mode == laser ]]; then flags=(--no-rgbd); fi
    rm -rf "$run"
    run_measured "$run.time.json" "${pin[@]}" "$littermap" -q reconstruct "$bag" -o "$run" \
      "${flags[@]}"
    "$littermap" eval trajectory "$run/trajectory.tum" "$truth/trajectory.tum" --json \
      >"$run/eval.json"
    "$littermap" eval trajectory "$run/odometry.tum" "$truth/trajectory.tum" --json \
      >"$run/odometry_eval.json"
    "$littermap" -q eval map "$bag" "$run/trajectory.tum" "$truth/trajectory.tum" --json \
      >"$run/map_eval.json"
    map_vs_truth=$(cells_ratio "$run/map_eval.json")
    python3 "$here/bench/trajectory_minutes.py" "$run/trajectory.tum" "$truth/trajectory.tum" \
      "$run/odometry.tum" >"$run/minutes.txt"
    ate_m=$(field "$run/eval.json" ate_rmse_m)
    printf '%s\t%s\t%s\n' "$world" "$mode" "$ate_m" >>"$rows"
    printf '%-22s %-7s %7s %8s %8s %8s %8s %8s %8s %6s %6s %7s %12s\n' "$run_name" "$mode" \
      "$(field "$run/quality.json" scans %d)" "$(field "$run.time.json" wall_s %.1f)" \
      "$(field "$run/quality.json" scans_per_s %.0f)" "$(field "$run.time.json" peak_mib %.0f)" \
      "$(printf %.3f "$ate_m")" "$(field "$run/odometry_eval.json" ate_rmse_m %.3f)" \
      "$(field "$run/eval.json" rpe_trans_mean_m %.3f)" \
      "$(field "$run/quality.json" loop_closures_accepted %d)" \
      "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["landmarks"]["loops_accepted"])' \
        "$run/quality.json")" \
      "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("rgbd", {}).get("loops_accepted", "-"))' \
        "$run/quality.json")" "$map_vs_truth"
  done
done
# Drift against time for the long runs: error percentiles and distance ratio minute by minute.
for run_name in "${run_names[@]}"; do
  for mode in hybrid laser; do
    minutes=$work/${run_name//\//-}/run-$mode/minutes.txt
    if [[ $(wc -l <"$minutes") -gt 8 ]]; then
      printf '\n%s %s, per minute:\n' "$run_name" "$mode"
      cat "$minutes"
    fi
  done
done
# The spread of each world and mode over its runs (draws).
python3 - "$rows" <<'EOF'
import collections, sys
ate = collections.defaultdict(list)
for line in open(sys.argv[1]):
    world, mode, value = line.split()
    ate[(world, mode)].append(float(value))
print()
print("%-20s %-7s %5s %10s %10s %10s" % ("world", "mode", "runs", "ATE_min_m", "ATE_mean_m",
                                         "ATE_max_m"))
for (world, mode), values in ate.items():
    print("%-20s %-7s %5d %10.3f %10.3f %10.3f" % (world, mode, len(values), min(values),
                                                   sum(values) / len(values), max(values)))
EOF

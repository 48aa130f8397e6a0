#!/usr/bin/env bash
# How far one park run's ATE moves when the reconstruction's options move by a hair: each run is
# reconstructed (hybrid) with the shipped options and once per entry of `perturbations` below,
# each one option moved by 0.2 % of its default, which no tuning could tell apart. A reconstruction
# takes discrete decisions (which routine places a scan, which loops are taken); where a decision
# sits at its threshold, the hair flips it and the run becomes another draw. The table says, per
# run, the shipped ATE and the least, mean and largest over the perturbed ones; the summary, what
# a comparison of two variants on these runs can resolve. Compare variants by these spreads, not
# by one draw each.
#   bench/slam_spread.sh [LITTERMAP] [WORK_DIR] [RUN...]
# RUN as in bench/slam_park.sh (simulated once, cached in WORK_DIR; the two scripts can share
# it). By default the small parks' acceptance set. Runs use every core: only the ATE is measured.
# A benchmark, not a test: it prints, it does not assert.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=bench/common.sh
source "$here/bench/common.sh"
park_bench_arguments "$@"
if [[ ${#run_names[@]} -eq 0 ]]; then
  run_names=(park_small park_{small,tilts}:{1,2,3} park_{small,tilts}@{101,102,103})
fi
# One option each, at 1.002 times its default (SlamOptions, TrackerOptions, KeyFrameMapOptions).
perturbations=(
  "match_sigma_floor_m: 0.00501"
  "match_sigma_floor_rad: 0.00501"
  "odometry_sigma_m: 0.01002"
  "odometry_sigma_rad: 0.00501"
  "gyro_sigma_rad: 0.001002"
  "key_frame_translation_m: 0.501"
)
mkdir -p "$work"
for k in "${!perturbations[@]}"; do
  printf '%s\n' "${perturbations[$k]}" >"$work/perturbation_$k.yaml"
done

jobs=$work/spread_jobs.txt
: >"$jobs"
for run_name in "${run_names[@]}"; do
  run_dir=$(simulate_park_run "$littermap" "$work" "$run_name")
  printf '%s\t%s\t-\n' "$run_name" "$run_dir" >>"$jobs"
  for k in "${!perturbations[@]}"; do
    printf '%s\t%s\t%s\n' "$run_name" "$run_dir" "$k" >>"$jobs"
  done
done

# reconstruct_one RUN_DIR K: the hybrid reconstruction with perturbation K (- for none, else
# WORK_DIR/perturbation_K.yaml) and its ATE in RUN_DIR/spread-K/eval.json.
reconstruct_one() {
  local run_dir=$1 k=$2 out=$1/spread-$2 options=()
  if [[ $k != - ]]; then options=(--options "$work/perturbation_$k.yaml"); fi
  rm -rf "$out"
  "$littermap" -q reconstruct "$run_dir/bag" -o "$out" "${options[@]}" >"$out.log" 2>&1
  "$littermap" eval trajectory "$out/trajectory.tum" "$run_dir/truth/trajectory.tum" --json \
    >"$out/eval.json"
}
export -f reconstruct_one
export littermap work
# shellcheck disable=SC2016  # $0 and $1 are the job's, expanded by the inner bash
cut -f2,3 "$jobs" | xargs -P "$(nproc)" -L 1 bash -c 'reconstruct_one "$0" "$1"'

python3 - "$jobs" "${perturbations[@]}" <<'EOF'
import json, statistics, sys
jobs, perturbations = sys.argv[1], sys.argv[2:]
runs = {}
for line in open(jobs):
    name, run_dir, k = line.rstrip("\n").split("\t")
    ate = json.load(open(f"{run_dir}/spread-{k}/eval.json"))["ate_rmse_m"]
    runs.setdefault(name, {})[k] = ate
print("perturbations (one each, 1.002 x the default):", "; ".join(perturbations))
print("%-20s %9s %9s %9s %9s %9s" % ("run", "shipped_m", "min_m", "mean_m", "max_m", "<=0.05"))
shipped, every = [], []
for name, ate in runs.items():
    others = [v for k, v in ate.items() if k != "-"]
    shipped.append(ate["-"])
    every += list(ate.values())
    print("%-20s %9.4f %9.4f %9.4f %9.4f %6d/%d" % (
        name, ate["-"], min(others), statistics.mean(others), max(others),
        sum(v <= 0.05 for v in ate.values()), len(ate)))
n = len(runs)
print()
print("shipped options: mean %.4f m, worst %.4f m, %d of %d runs <= 0.05 m" % (
    statistics.mean(shipped), max(shipped), sum(v <= 0.05 for v in shipped), n))
per_draw = [[ate[k] for ate in runs.values()] for k in runs[next(iter(runs))]]
means = [statistics.mean(d) for d in per_draw]
print("over the %d option sets: mean of the runs' ATE %.4f-%.4f m (sd %.4f), worst run %.4f-%.4f m,"
      " runs <= 0.05 m %d-%d of %d" % (
          len(per_draw), min(means), max(means), statistics.stdev(means) if len(means) > 1 else 0,
          min(max(d) for d in per_draw), max(max(d) for d in per_draw),
          min(sum(v <= 0.05 for v in d) for d in per_draw),
          max(sum(v <= 0.05 for v in d) for d in per_draw), n))
print("all %d reconstructions: mean %.4f m, %.0f %% <= 0.05 m" % (
    len(every), statistics.mean(every), 100 * sum(v <= 0.05 for v in every) / len(every)))
EOF

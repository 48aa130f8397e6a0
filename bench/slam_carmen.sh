#!/usr/bin/env bash
# SLAM acceptance benchmark on the CARMEN logs (../shared/datasets/README.md): every log imported
# with --odometry-noise 1, 2 and 3, reconstructed, and evaluated against the reference with
# `littermap eval trajectory` (ATE RMSE after Horn alignment, RPE over 1 m pairs).
# Prints one table row per log x seed: odometry ATE, littermap ATE, RPE, loops, scans/s (each
# reconstruction pinned to one core), and map_vs_ref: the 5 cm cells the scans occupy when drawn
# with littermap's trajectory, over those with the reference's (`littermap eval map`; < 1: the
# scans lie more consistently over each other than with the reference poses); ref_moves and
# est_moves: how far (ATE RMSE, metres) the reference and littermap's trajectory move when settled
# onto their scans (`littermap eval settle`): how far the log's own scans move the reference;
# noise_free_ATE: littermap's ATE when the odometry is the reference's own motion, without noise
# (once a log): how far the log's scans pull a trajectory from the reference when the odometry
# holds it there. Where it is as large as the seeds' ATE, the odometry noise is not what the ATE
# measures. rel_tr_m (n): the mean translational error on the manually verified relations of
# Kuemmerle et al. 2009 (`littermap eval relations`, the benchmark's definition) over the n
# relations with both ends in the thinned log, for intel, aces and csail.
# A second table runs the benchmark's raw logs (../shared/datasets/carmen-raw) with the robots'
# real odometry, every relation usable: the fair comparison with the published figures
# (Cartographer: intel 0.023, aces 0.038, csail 0.032 m).
#   bench/slam_carmen.sh [LITTERMAP] [WORK_DIR] [LOG_NAME...]
# SEEDS="1 2 3" picks the odometry noise seeds, OPTIONS=FILE.yaml passes reconstruct --options.
# A benchmark, not a test: it prints, it does not assert.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
littermap=${1:-$here/build/cli/littermap}
work=${2:-${TMPDIR:-/tmp}/littermap-slam-carmen}
shift $(( $# > 2 ? 2 : $# ))
datasets=${LITTERMAP_DATASETS_DIR:-$here/../shared/datasets}/carmen
logs=("$@")
if [[ ${#logs[@]} -eq 0 ]]; then
  logs=(aces intel csail freiburg-campus seattle orebro freiburg-101 edmonton acapulco)
fi
seeds=${SEEDS:-"1 2 3"}
options=()
if [[ -n ${OPTIONS:-} ]]; then options=(--options "$OPTIONS"); fi
mkdir -p "$work"
# shellcheck source=bench/common.sh
source "$here/bench/common.sh"

relations=$datasets/relations
# relations_row TRAJ LOG: "mean (n)" of the translational relation error, "-" without relations.
relations_row() {
  if [[ ! -f $relations/$2.relations ]]; then echo -; return; fi
  "$littermap" eval relations "$1" "$relations/$2.relations" --scanmap "$relations/$2.scanmap" \
    --json >"$1.relations.json"
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))
print("%.4f(%d)" % (r["metric_evaluator"]["trans_m"]["mean"], r["used"]))' "$1.relations.json"
}

printf '%-16s %4s %9s %9s %9s %9s %6s %6s %8s %7s %10s %9s %9s %14s %12s\n' log seed odom_ATE ATE \
  RPE_tr RPE_rot loops rej scans/s time_s map_vs_ref ref_moves est_moves noise_free_ATE rel_tr_m
declare -A ref_settled
for log in "${logs[@]}"; do
  # The reference's own motion as the odometry: the same scans, nothing for SLAM to correct.
  exact=$work/$log-exact
  if [[ ! -d $exact ]]; then
    "$littermap" -q import carmen "$datasets/$log-corrected.log.gz" -o "$exact" \
      --reference "$work/$log-ref.tum" >/dev/null
  fi
  exact_run=$work/run-$log-exact
  rm -rf "$exact_run"
  noise_free=n/a
  if "${pin[@]}" "$littermap" -q reconstruct "$exact" -o "$exact_run" "${options[@]}" >/dev/null \
    2>"$exact_run.stderr"; then
    "$littermap" eval trajectory "$exact_run/trajectory.tum" "$work/$log-ref.tum" --json \
      >"$exact_run/eval.json"
    noise_free=$(field "$exact_run/eval.json" ate_rmse_m)
  else
    echo "$log without odometry noise: reconstruct failed: $(cat "$exact_run.stderr")"
  fi
  for seed in $seeds; do
    bag=$work/$log-$seed
    ref=$work/$log-ref.tum
    run=$work/run-$log-$seed
    if [[ ! -d $bag ]]; then
      "$littermap" -q import carmen "$datasets/$log-corrected.log.gz" -o "$bag" \
        --reference "$ref" --odometry-noise "$seed" >/dev/null
    fi
    rm -rf "$run"
    "${pin[@]}" "$littermap" -q reconstruct "$bag" -o "$run" "${options[@]}" >/dev/null \
      2>"$run.stderr" || {
      echo "$log $seed: reconstruct failed: $(cat "$run.stderr")"; continue; }
    "$littermap" eval trajectory "$run/odometry.tum" "$ref" --json >"$run/odometry_eval.json"
    "$littermap" eval trajectory "$run/trajectory.tum" "$ref" --json >"$run/eval.json"
    "$littermap" -q eval map "$bag" "$run/trajectory.tum" "$ref" --json >"$run/map_eval.json"
    map_vs_ref=$(cells_ratio "$run/map_eval.json")
    if [[ -z ${ref_settled[$log]:-} ]]; then  # once a log and run: the scans are the seeds' same
      "$littermap" -q eval settle "$bag" "$ref" --json >"$work/$log-ref-settle.json.part"
      mv "$work/$log-ref-settle.json.part" "$work/$log-ref-settle.json"
      ref_settled[$log]=1
    fi
    "$littermap" -q eval settle "$bag" "$run/trajectory.tum" --json >"$run/settle.json"
    printf '%-16s %4s %9s %9s %9s %9s %6s %6s %8.0f %7.2f %10s %9s %9s %14s %12s\n' "$log" "$seed" \
      "$(field "$run/odometry_eval.json" ate_rmse_m)" "$(field "$run/eval.json" ate_rmse_m)" \
      "$(field "$run/eval.json" rpe_trans_mean_m)" "$(field "$run/eval.json" rpe_rot_mean_deg)" \
      "$(field "$run/quality.json" loop_closures_accepted %d)" \
      "$(field "$run/quality.json" loop_closures_rejected %d)" \
      "$(field "$run/quality.json" scans_per_s)" "$(field "$run/quality.json" run_time_s)" \
      "$map_vs_ref" "$(field "$work/$log-ref-settle.json" ate_rmse_m)" \
      "$(field "$run/settle.json" ate_rmse_m)" "$noise_free" \
      "$(relations_row "$run/trajectory.tum" "$log")"
  done
done

raw=${LITTERMAP_DATASETS_DIR:-$here/../shared/datasets}/carmen-raw
echo
printf '%-8s %7s %8s %8s %12s %10s %8s %12s %10s %6s\n' raw_log scans scans/s rel_used \
  rel_tr_m rel_tr_sd rel_max over_0.5m carto_tr_m loops
for log in ${RAW_LOGS:-intel aces csail}; do
  bag=$work/raw-$log
  run=$work/run-raw-$log
  if [[ ! -d $bag ]]; then "$littermap" -q import carmen "$raw/$log.clf.gz" -o "$bag" >/dev/null; fi
  rm -rf "$run"
  "${pin[@]}" "$littermap" -q reconstruct "$bag" -o "$run" "${options[@]}" >/dev/null
  "$littermap" -q eval relations "$run/trajectory.tum" "$raw/$log.relations" \
    --log "$raw/$log.clf.gz" --json >"$run/relations.json"
  python3 - "$run/relations.json" "$run/quality.json" "$log" <<'EOF2'
import json, sys
r, q = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
m, c = r["metric_evaluator"], r["cartographer"]
print("%-8s %7d %8.0f %8d %12.4f %10.4f %8.3f %12d %10.4f %6d" % (
    sys.argv[3], q["scans"], q["scans_per_s"], r["used"], m["trans_m"]["mean"],
    m["trans_m"]["stddev"], m["trans_m"]["max"], m["over_large_error"], c["trans_m"]["mean"],
    q["loop_closures_accepted"]))
EOF2
done

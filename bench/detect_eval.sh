#!/usr/bin/env bash
# Litter detection scored on simulated parks whose seeds the shipped model was not trained on
# (scripts/train-model.sh uses 11-18 and 41-56): simulate, detect with the true trajectory
# (detection alone) and with the reconstructed one (the pipeline), and score items against the
# truth.
#   bench/detect_eval.sh LITTERMAP_BINARY WORK_DIR [SEED...]
#     (default seeds 7 21-23 101-103 201-203)
#   WORLD=samples/worlds/park_hard.yaml bench/detect_eval.sh ... 36   (another world; 36 is its own)
#   MIN_CONFIDENCE=0.25 bench/detect_eval.sh ...   (scores only the items at least that sure)
#   MODEL=other.yml.gz bench/detect_eval.sh ...      (another classifier than the shipped one)
# Prints one table row per seed and trajectory (slam rows also give the run's ATE, since items
# placed with it inherit its error), then the totals over the seeds per trajectory. "recall by
# masks" splits the recall by the masks (every 10th frame) an item was visible in: 1 is a glimpse
# at the edge of the image or of the depth range, 3+ an item the robot passed by. About 6
# minutes per seed on one core.
set -euo pipefail
littermap=$1
work=$2
shift 2
seeds=("$@")
if [[ ${#seeds[@]} -eq 0 ]]; then seeds=(7 21 22 23 101 102 103 201 202 203); fi
here=$(cd "$(dirname "$0")/.." && pwd)
world=${WORLD:-$here/samples/worlds/park_small.yaml}
mkdir -p "$work"
model=()
if [[ -n ${MODEL:-} ]]; then model=(--model "$MODEL"); fi
printf "%-5s %-10s %8s %9s %6s %6s %8s %10s %14s %6s %6s  %s\n" seed trajectory ate_m precision \
  recall f1 "class" litter/nat "truth litter" tp fp "recall by masks 1/2/3+"
evals=()
for seed in "${seeds[@]}"; do
  run="$work/seed$seed"
  if [[ ! -f "$run/truth/masks/visible.csv" ]]; then
    "$littermap" simulate "$world" -o "$run/bag" --truth "$run/truth" --seed "$seed" --quiet >/dev/null
  fi
  if [[ ! -f "$run/run/trajectory.tum" ]]; then
    "$littermap" reconstruct "$run/bag" -o "$run/run" --quiet >/dev/null
  fi
  for source in truth slam; do
    out="$run/detect-$source"
    trajectory="$run/truth/trajectory.tum"
    [[ $source == slam ]] && trajectory="$run/run/trajectory.tum"
    if [[ ! -f "$out/items.csv" ]]; then
      "$littermap" detect "$run/bag" --run "$run/run" -o "$out" --trajectory "$trajectory" \
        "${model[@]}" --quiet >"$out.log"
    fi
    # Items of the reconstructed run are in its map frame: align them as ATE aligns trajectories.
    align=()
    [[ $source == slam ]] && align=(--align "$run/run/trajectory.tum" "$run/truth/trajectory.tum")
    "$littermap" eval detections "$out/items.csv" "$run/truth/litter.csv" \
      --natural "$run/truth/natural.csv" --visible "$run/truth/masks/visible.csv" "${align[@]}" \
      --min-confidence "${MIN_CONFIDENCE:-0}" --json >"$out/eval.json"
    evals+=("$source" "$out/eval.json")
    ate=0
    if [[ $source == slam ]]; then
      ate=$("$littermap" eval trajectory "$run/run/trajectory.tum" "$run/truth/trajectory.tum" \
        --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["ate_rmse_m"])')
    fi
    python3 - "$seed" "$source" "$out/eval.json" "$ate" <<'PY'
import json, sys
seed, source, path, ate = sys.argv[1:5]
m = json.load(open(path))
by_masks = " ".join("%d/%d" % (b["tp"], b["truth"]) for b in m["recall_by_masks"].values())
print("%-5s %-10s %8.3f %9.3f %6.3f %6.3f %8.3f %10.3f %14d %6d %6d  %s" % (
    seed, source, float(ate), m["precision"], m["recall"], m["f1"], m["class_accuracy"],
    m["litter_natural_accuracy"], m["truth_litter"], m["true_positives"], m["false_positives"],
    by_masks))
PY
  done
done
# Totals over the seeds: items of all parks pooled, per trajectory.
python3 - "${evals[@]}" <<'PY'
import collections, json, sys
totals = collections.defaultdict(collections.Counter)
for source, path in zip(sys.argv[1::2], sys.argv[2::2]):
    m = json.load(open(path))
    t = totals[source]
    for key in ("true_positives", "false_positives", "false_negatives"):
        t[key] += m[key]
    for masks, b in m["recall_by_masks"].items():
        t["tp " + masks] += b["tp"]
        t["truth " + masks] += b["truth"]
def ratio(numerator, denominator):  # over nothing, 1: as eval detections counts it
    return numerator / denominator if denominator else 1.0
print()
for source, t in totals.items():
    tp, fp, fn = t["true_positives"], t["false_positives"], t["false_negatives"]
    by_masks = "  ".join("%s: %d/%d %.3f" % (k, t["tp " + k], t["truth " + k],
                                             ratio(t["tp " + k], t["truth " + k]))
                         for k in ("1", "2", "3+"))
    print("all seeds, %s: precision %.3f recall %.3f (tp %d fp %d fn %d); recall by masks %s" % (
        source, ratio(tp, tp + fp), ratio(tp, tp + fn), tp, fp, fn, by_masks))
PY

#!/usr/bin/env bash
# Litter items scored by two-fold cross-validation over the classifier's training parks: a model
# trained on the first half of the seeds detects on the second half and the other way round
# (true trajectory), so every seed is scored by a model that never saw it. Its 48 parks hold
# about 680 visible litter items, far more than the held-out worlds of bench/detect_eval.sh: the
# steadier yardstick for detection and fusion rules. With the default seeds one fold is the
# shipped model's 24 (11-18 and 41-56) and the other 57-80.
#   bench/detect_crossval.sh LITTERMAP_BINARY WORK_DIR [SEED...]   (default 11-18 and 41-80)
#   OPTIONS=samples/detect_full.yaml bench/detect_crossval.sh ...    (detect's options file)
# The fold models are made by scripts/train-model.sh in WORK_DIR, so a folder of it is reused
# (simulations and samples); models and detections are made again on every call. Prints one row
# per seed and the totals.
set -euo pipefail
littermap=$1
work=$2
shift 2
seeds=("$@")
if [[ ${#seeds[@]} -eq 0 ]]; then
  seeds=(11 12 13 14 15 16 17 18 {41..80})
fi
if [[ ${#seeds[@]} -lt 2 ]]; then
  echo "detect_crossval.sh: needs at least two seeds, one for each fold" >&2
  exit 1
fi
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=${JOBS:-$(nproc)}
mkdir -p "$work"

# Each fold's model, made as the shipped one is (simulations and samples are cut when missing).
half=$((${#seeds[@]} / 2))
folds=("${seeds[*]:0:half}" "${seeds[*]:half}")
for f in 0 1; do
  # shellcheck disable=SC2086  # a fold is a list of seeds
  JOBS=$jobs "$here/scripts/train-model.sh" "$littermap" "$work" "$work/crossval_model_$f.yml.gz" \
    ${folds[$f]} >/dev/null
done

detect() {
  local seed=$1 model=$2 run="$work/seed$1" options=()
  if [[ -n ${OPTIONS:-} ]]; then options=(--options "$OPTIONS"); fi
  mkdir -p "$run/crossval_run"
  rm -rf "$run/crossval"
  "$littermap" detect "$run/bag" --run "$run/crossval_run" -o "$run/crossval" \
    --trajectory "$run/truth/trajectory.tum" --model "$model" "${options[@]}" --quiet >/dev/null
  "$littermap" eval detections "$run/crossval/items.csv" "$run/truth/litter.csv" \
    --natural "$run/truth/natural.csv" --visible "$run/truth/masks/visible.csv" --json \
    >"$run/crossval/eval.json"
}
export -f detect
export littermap work
export OPTIONS=${OPTIONS:-}
# shellcheck disable=SC2016  # the inner shell expands $0 and $1
{
  for seed in ${folds[0]}; do echo "$seed $work/crossval_model_1.yml.gz"; done
  for seed in ${folds[1]}; do echo "$seed $work/crossval_model_0.yml.gz"; done
} | xargs -P "$jobs" -L 1 bash -c 'detect "$0" "$1"'

python3 - "$work" "${seeds[@]}" <<'PY'
import json, sys
work, seeds = sys.argv[1], sys.argv[2:]
print("%-5s %9s %6s %6s %14s %6s %6s %6s" % ("seed", "precision", "recall", "f1", "truth litter",
                                             "tp", "fp", "fn"))
tp = fp = fn = 0
for seed in seeds:
    m = json.load(open("%s/seed%s/crossval/eval.json" % (work, seed)))
    tp += m["true_positives"]; fp += m["false_positives"]; fn += m["false_negatives"]
    print("%-5s %9.3f %6.3f %6.3f %14d %6d %6d %6d" % (seed, m["precision"], m["recall"], m["f1"],
          m["truth_litter"], m["true_positives"], m["false_positives"], m["false_negatives"]))
p = tp / (tp + fp) if tp + fp else 1.0
r = tp / (tp + fn) if tp + fn else 1.0
f1 = 2 * p * r / (p + r) if p + r else 0.0
print("%-5s %9.3f %6.3f %6.3f %14d %6d %6d %6d" % ("all", p, r, f1, tp + fn, tp, fp, fn))
PY

#!/usr/bin/env bash
# Litter items scored by two-fold cross-validation over the classifier's training parks: a model
# trained on the first half of the seeds detects on the second half and the other way round
# (true trajectory), so every seed is scored by a model that never saw it. Its 48 parks hold
# about 680 visible litter items, far more than the held-out worlds of bench/detect_eval.sh: the
# steadier yardstick for detection and fusion rules. With the default seeds one fold is the
# shipped model's 24 (11-18 and 41-56) and the other 57-80.
#   bench/detect_crossval.sh LITTERMAP_BINARY WORK_DIR [SEED...]   (default 11-18 and 41-80)
#   OPTIONS=samples/detect_full.yaml bench/detect_crossval.sh ...    (detect's options file)
#   MODEL=samples/models/litter_classifier.yml.gz bench/detect_crossval.sh ...
#       (no training: MODEL, trained on the first half, detects on the second half alone; the
#       shipped model's held-out check, in a quarter of the time)
#   THRESHOLDS="0.55 0.6 0.65 0.7" bench/detect_crossval.sh ...
#       (also the totals at each item threshold, min_litter_probability: detect runs at the
#       lowest of them and the others are exact from its items, so one pass chooses it)
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

half=$((${#seeds[@]} / 2))
folds=("${seeds[*]:0:half}" "${seeds[*]:half}")
if [[ -n ${MODEL:-} ]]; then
  # The given model on the second half; its parks are simulated when missing.
  simulate() {
    local run="$work/seed$1"
    if [[ -f $run/truth/litter.csv ]]; then return 0; fi
    "$littermap" simulate "$here/samples/worlds/park_small.yaml" -o "$run/bag" --truth "$run/truth" \
      --seed "$1" --quiet
  }
  export -f simulate
  export littermap work here
  read -ra seeds <<<"${folds[1]}"
  printf '%s\n' "${seeds[@]}" | xargs -P "$jobs" -I{} bash -c 'simulate {}'
else
  # Each fold's model, made as the shipped one is (simulations and samples cut when missing).
  for f in 0 1; do
    # shellcheck disable=SC2086  # a fold is a list of seeds
    JOBS=$jobs "$here/scripts/train-model.sh" "$littermap" "$work" \
      "$work/crossval_model_$f.yml.gz" ${folds[$f]} >/dev/null
  done
fi

# Detect's options: OPTIONS, with the lowest of THRESHOLDS as the item threshold.
options_file=${OPTIONS:-}
read -ra thresholds <<<"${THRESHOLDS:-}"
if [[ ${#thresholds[@]} -gt 0 ]]; then
  options_file=$work/crossval_options.yaml
  if [[ -n ${OPTIONS:-} ]]; then
    grep -v '^min_litter_probability:' "$OPTIONS" >"$options_file" || true
  else
    : >"$options_file"
  fi
  lowest=$(printf '%s\n' "${thresholds[@]}" | sort -g | head -1)
  printf 'min_litter_probability: %s\n' "$lowest" >>"$options_file"
fi

detect() {
  local seed=$1 model=$2 run="$work/seed$1" options=()
  if [[ -n $options_file ]]; then options=(--options "$options_file"); fi
  mkdir -p "$run/crossval_run"
  rm -rf "$run/crossval"
  "$littermap" detect "$run/bag" --run "$run/crossval_run" -o "$run/crossval" \
    --trajectory "$run/truth/trajectory.tum" --model "$model" "${options[@]}" --quiet >/dev/null
}
export -f detect
export littermap work options_file
# shellcheck disable=SC2016  # the inner shell expands $0 and $1
{
  if [[ -n ${MODEL:-} ]]; then
    for seed in ${folds[1]}; do echo "$seed $MODEL"; done
  else
    for seed in ${folds[0]}; do echo "$seed $work/crossval_model_1.yml.gz"; done
    for seed in ${folds[1]}; do echo "$seed $work/crossval_model_0.yml.gz"; done
  fi
} | xargs -P "$jobs" -L 1 bash -c 'detect "$0" "$1"'

# Every seed's items scored as detected, then at each of THRESHOLDS (detect ran at the lowest). An
# item that is litter at threshold t >= the run's is one whose litter probability reaches t (its
# class is then the run's), so each sweep row is what detect run at t would have given; an item
# the run's threshold made natural stays natural above it.
python3 - "$littermap" "$work" "${thresholds[*]}" "${seeds[@]}" <<'PY'
import csv, json, subprocess, sys
littermap, work, thresholds, seeds = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4:]

def score(run, items):
    return json.loads(subprocess.run(
        [littermap, "eval", "detections", items, run + "/truth/litter.csv", "--natural",
         run + "/truth/natural.csv", "--visible", run + "/truth/masks/visible.csv", "--json"],
        check=True, capture_output=True, text=True).stdout)

def at_threshold(run, rows, t):
    items = run + "/crossval/items_at_threshold.csv"
    with open(items, "w", newline="") as f:
        out = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["id"])
        out.writeheader()
        for row in rows:
            row = dict(row)
            if row["litter"] == "1" and float(row["litter_probability"]) < float(t):
                row["litter"], row["class"] = "0", "natural"
            out.writerow(row)
    return score(run, items)

def totals(metrics):
    tp = sum(m["true_positives"] for m in metrics)
    fp = sum(m["false_positives"] for m in metrics)
    fn = sum(m["false_negatives"] for m in metrics)
    p = tp / (tp + fp) if tp + fp else 1.0
    r = tp / (tp + fn) if tp + fn else 1.0
    return p, r, 2 * p * r / (p + r) if p + r else 0.0, tp, fp, fn

thresholds = sorted(thresholds, key=float)
as_run, swept = [], {t: [] for t in thresholds}
for seed in seeds:
    run = "%s/seed%s" % (work, seed)
    as_run.append(score(run, run + "/crossval/items.csv"))
    with open(run + "/crossval/items.csv") as f:
        rows = list(csv.DictReader(f))
    for t in thresholds:
        swept[t].append(at_threshold(run, rows, t))

print("%-5s %9s %6s %6s %14s %6s %6s %6s" % ("seed", "precision", "recall", "f1", "truth litter",
                                             "tp", "fp", "fn"))
for seed, m in zip(seeds, as_run):
    print("%-5s %9.3f %6.3f %6.3f %14d %6d %6d %6d" % (seed, m["precision"], m["recall"], m["f1"],
          m["truth_litter"], m["true_positives"], m["false_positives"], m["false_negatives"]))
p, r, f1, tp, fp, fn = totals(as_run)
print("%-5s %9.3f %6.3f %6.3f %14d %6d %6d %6d" % ("all", p, r, f1, tp + fn, tp, fp, fn))
if thresholds:
    print("\nitem threshold sweep (the table above is at %s):" % thresholds[0])
    print("%-9s %9s %6s %6s %6s %6s %6s %s" % ("threshold", "precision", "recall", "f1", "tp",
                                              "fp", "fn",
                                              "seeds with precision >= 0.95, recall >= 0.90"))
    for t in thresholds:
        good = sum(m["precision"] >= 0.95 and m["recall"] >= 0.90 for m in swept[t])
        print("%-9s %9.3f %6.3f %6.3f %6d %6d %6d %d of %d" % ((t,) + totals(swept[t]) +
                                                              (good, len(seeds))))
PY

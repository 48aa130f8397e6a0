#!/usr/bin/env bash
# Trains the litter classifier the way samples/models/litter_classifier.yml.gz was made: simulated
# surveys of the sample park with other seeds (other worlds: terrain, litter, look-alikes), object
# crops labelled from their ground truth, and `littermap train` on all of them.
#   scripts/train-model.sh LITTERMAP_BINARY WORK_DIR MODEL_OUT [SEED...]
# Seeds default to 11-18 and 41-56; 7 (the demo's world), 21-23, 101-103 and 201-203 are kept
# for testing, 57-80 for cross-validation (bench/detect_crossval.sh). About 3 minutes per seed on
# one core; JOBS (default: the number of cores) seeds are simulated at once. Every seed's crops
# are the same whichever runs first, so the model is too.
set -euo pipefail
littermap=$1
work=$2
model=$3
shift 3
seeds=("$@")
if [[ ${#seeds[@]} -eq 0 ]]; then
  seeds=(11 12 13 14 15 16 17 18 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56)
fi
here=$(cd "$(dirname "$0")/.." && pwd)
world="$here/samples/worlds/park_small.yaml"
jobs=${JOBS:-$(nproc)}
mkdir -p "$work"

cut_samples() {
  local seed=$1 run="$work/seed$1"
  if [[ -f "$run/samples/labels.csv" ]]; then return 0; fi
  echo "== seed $seed: simulating and cutting samples"
  "$littermap" simulate "$world" -o "$run/bag" --truth "$run/truth" --seed "$seed" --quiet
  "$littermap" samples "$run/bag" --truth "$run/truth" -o "$run/samples" --every 3 \
    --options "$here/samples/detect_full.yaml" --quiet
}
export -f cut_samples
export littermap work world here
printf '%s\n' "${seeds[@]}" | xargs -P "$jobs" -I{} bash -c 'cut_samples {}'

sample_dirs=()
for seed in "${seeds[@]}"; do sample_dirs+=("$work/seed$seed/samples"); done
"$littermap" train "${sample_dirs[@]}" -o "$model"

#!/usr/bin/env bash
# Trains the litter classifier the way samples/models/litter_classifier.yml.gz was made: simulated
# surveys of the sample park with other seeds (other worlds: terrain, litter, look-alikes), object
# crops labelled from their ground truth, and `littermap train` on all of them.
#   scripts/train-model.sh LITTERMAP_BINARY WORK_DIR MODEL_OUT [SEED...]
# Seeds default to 11-18; 7 (the demo's world) and 21-23 are kept for testing. About 3 minutes
# per seed on one core.
set -euo pipefail
littermap=$1
work=$2
model=$3
shift 3
seeds=("$@")
if [[ ${#seeds[@]} -eq 0 ]]; then seeds=(11 12 13 14 15 16 17 18); fi
here=$(cd "$(dirname "$0")/.." && pwd)
world="$here/samples/worlds/park_small.yaml"
mkdir -p "$work"
sample_dirs=()
for seed in "${seeds[@]}"; do
  run="$work/seed$seed"
  if [[ ! -f "$run/samples/labels.csv" ]]; then
    echo "== seed $seed: simulating and cutting samples"
    "$littermap" simulate "$world" -o "$run/bag" --truth "$run/truth" --seed "$seed" --quiet
    "$littermap" samples "$run/bag" --truth "$run/truth" -o "$run/samples" --every 3 --quiet
  fi
  sample_dirs+=("$run/samples")
done
"$littermap" train "${sample_dirs[@]}" -o "$model"

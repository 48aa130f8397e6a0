#!/usr/bin/env bash
# Runs the furthest littermap stage that exists on the sample data and says where the result is.
#   scripts/demo.sh LITTERMAP_BINARY OUT_DIR
set -euo pipefail
littermap=$1
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
sample="$here/../shared/datasets/carmen/intel-corrected.log.gz"

if [[ ! -f "$sample" ]]; then
  echo "littermap demo: the sample log $sample is not there" >&2
  exit 2
fi
rm -rf "$out/intel"
mkdir -p "$out"
echo "littermap demo: importing the Intel Research Lab laser log into a run bag"
"$littermap" import carmen "$sample" -o "$out/intel" --reference "$out/intel-reference.tum" \
  --odometry-noise 1
echo
"$littermap" info "$out/intel"
echo
echo "littermap demo: run bag in $out/intel, reference trajectory in $out/intel-reference.tum"
echo "(later stages — reconstruct, detect, heatmap, report — will extend this demo as they land)"

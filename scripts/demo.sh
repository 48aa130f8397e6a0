#!/usr/bin/env bash
# Runs the furthest littermap stages that exist on the samples and says where the results are:
# a simulated survey of samples/worlds/park_small.yaml and the real Intel Research Lab laser log,
# each recorded into a run bag, reconstructed, and scored against its ground truth; litter is
# detected in the park run's camera frames, scored, and goes into a site database and a density
# map.
#   scripts/demo.sh LITTERMAP_BINARY OUT_DIR
set -euo pipefail
littermap=$1
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
world="$here/samples/worlds/park_small.yaml"
intel="$here/../shared/datasets/carmen/intel-corrected.log.gz"

for input in "$world" "$intel"; do
  if [[ ! -f "$input" ]]; then
    echo "littermap demo: $input is not there" >&2
    exit 2
  fi
done
rm -rf "$out/park_small" "$out/intel"
mkdir -p "$out/park_small" "$out/intel"

step() { echo; echo "== $*"; }

step "simulating a survey of the sample park ($world)"
"$littermap" simulate "$world" -o "$out/park_small/bag" --truth "$out/park_small/truth" \
  --contact-sheet "$out/park_small/contact_sheet.png"
step "reconstructing the simulated run"
"$littermap" reconstruct "$out/park_small/bag" -o "$out/park_small/run"
step "trajectory error against the simulator's ground truth"
"$littermap" eval trajectory "$out/park_small/run/trajectory.tum" \
  "$out/park_small/truth/trajectory.tum"

step "detecting litter in the simulated run's RGB-D frames"
"$littermap" detect "$out/park_small/bag" --run "$out/park_small/run" \
  --debug-frames "$out/park_small/run/segmentation"
step "detected litter items against the simulator's ground truth"
echo "(items are placed with the reconstructed trajectory: its error above moves them too)"
"$littermap" eval detections "$out/park_small/run/items.csv" "$out/park_small/truth/litter.csv" \
  --natural "$out/park_small/truth/natural.csv" --visible "$out/park_small/truth/masks/visible.csv" \
  --align "$out/park_small/run/trajectory.tum" "$out/park_small/truth/trajectory.tum"

step "site database and litter density map of the sample park"
"$littermap" site init "$out/park_small/site.gpkg" --name "park_small"
"$littermap" ingest "$out/park_small/site.gpkg" "$out/park_small/run" --name park_small-seed7
"$littermap" heatmap "$out/park_small/site.gpkg" -o "$out/park_small/maps"

step "importing the Intel Research Lab laser log (real data, corrupted odometry, seed 1)"
"$littermap" import carmen "$intel" -o "$out/intel/bag" --reference "$out/intel/reference.tum" \
  --odometry-noise 1
step "reconstructing the Intel run"
"$littermap" reconstruct "$out/intel/bag" -o "$out/intel/run"
step "trajectory error against the log's corrected poses"
"$littermap" eval trajectory "$out/intel/run/trajectory.tum" "$out/intel/reference.tum"

step "results"
cat <<EOF
simulated park: bag $out/park_small/bag, ground truth $out/park_small/truth,
                map $out/park_small/run/map.png, trajectory $out/park_small/run/trajectory.tum,
                contact sheet $out/park_small/contact_sheet.png,
                litter items $out/park_small/run/items.csv (detections.csv per frame,
                segmentation pictures in $out/park_small/run/segmentation/),
                site database $out/park_small/site.gpkg (a GeoPackage),
                density $out/park_small/maps/density.tif and density.png, hotspots.csv
Intel lab:      bag $out/intel/bag, map $out/intel/run/map.png,
                trajectory $out/intel/run/trajectory.tum
(the HTML report extends this demo when it lands)
EOF

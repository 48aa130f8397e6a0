#!/usr/bin/env bash
# Runs littermap end to end on the samples and says where the results are: three weekly survey
# runs of the simulated sample park (samples/worlds/park_small.yaml; the litter changes between
# weeks) go through `littermap survey` into one site database and one HTML report, the first
# run scored against the simulator's ground truth; then the real Intel Research Lab laser log is
# reconstructed and scored.
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

park="$out/park_small"
site="$park/site.gpkg"
# An example georeference, so the report shows GPS coordinates: the park's south-west corner
# dock at UTM zone 32N (EPSG:32632) 691000 E, 5334000 N, in Munich.
"$littermap" site init "$site" --name "Sample park" --crs EPSG:32632 --origin 691000 5334000
for week in 1 2 3; do
  day=$(printf '%02d' $((1 + 7 * (week - 1))))
  step "week $week: simulating a survey of the sample park on 2026-11-$day"
  "$littermap" simulate "$world" -o "$park/week$week/bag" --truth "$park/week$week/truth" \
    --run-seed "$week" --litter-day $((week - 1)) --start-time "2026-11-${day}T09:00"
  step "week $week: littermap survey (reconstruct, detect, ingest, heatmap, report)"
  "$littermap" survey "$park/week$week/bag" --site "$site" -o "$park/week$week" \
    --name "week $week" --every 2
done

step "week 1 against the simulator's ground truth: trajectory, then litter items"
echo "(items are placed with the reconstructed trajectory: its error moves them too)"
"$littermap" eval trajectory "$park/week1/run/trajectory.tum" "$park/week1/truth/trajectory.tum"
"$littermap" eval detections "$park/week1/run/items.csv" "$park/week1/truth/litter.csv" \
  --natural "$park/week1/truth/natural.csv" --visible "$park/week1/truth/masks/visible.csv" \
  --align "$park/week1/run/trajectory.tum" "$park/week1/truth/trajectory.tum"

step "importing the Intel Research Lab laser log (real data, corrupted odometry, seed 1)"
"$littermap" import carmen "$intel" -o "$out/intel/bag" --reference "$out/intel/reference.tum" \
  --odometry-noise 1
step "reconstructing the Intel run"
"$littermap" reconstruct "$out/intel/bag" -o "$out/intel/run"
step "trajectory error against the log's corrected poses"
"$littermap" eval trajectory "$out/intel/run/trajectory.tum" "$out/intel/reference.tum"

step "results"
cat <<EOF
sample park:  site database $site (a GeoPackage: open it in QGIS),
              per week in $park/weekN/: bag/, truth/, run/ (map.png, trajectory.tum,
              items.csv), maps/ (density.tif, effort.tif, density.png, hotspots.csv, items.geojson)
Intel lab:    bag $out/intel/bag, map $out/intel/run/map.png,
              trajectory $out/intel/run/trajectory.tum

The report for park staff: $park/week3/report/index.html
EOF

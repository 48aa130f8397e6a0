# shellcheck shell=bash
# shellcheck disable=SC2034  # the globals set here are used by the scripts that source this file
# Shared by the benchmark scripts (sourced, not run).

# The checkout these scripts belong to.
bench_checkout=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# The command prefix that pins a run to one core, when taskset is there.
pin=()
if command -v taskset >/dev/null; then pin=(taskset -c 0); fi

# field JSON_FILE KEY [FORMAT]: a top-level value of a JSON file, printf-formatted (default %.4f).
field() {
  python3 -c 'import json,sys; print(sys.argv[3] % json.load(open(sys.argv[1]))[sys.argv[2]])' \
    "$1" "$2" "${3:-%.4f}"
}

# cells_ratio MAP_JSON: occupied cells of the first trajectory of `littermap eval map --json` over
# those of the second.
cells_ratio() {
  python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["trajectories"]
print("%.3f" % (t[0]["occupied_cells"] / t[1]["occupied_cells"]))' "$1"
}

# park_bench_arguments [LITTERMAP] [WORK_DIR] [RUN...]: the park benchmarks' arguments, as the
# globals littermap (default: this checkout's build), work (default: a folder in TMPDIR shared by
# them, where the simulations are cached) and run_names (empty when none are given).
park_bench_arguments() {
  littermap=${1:-$bench_checkout/build/cli/littermap}
  work=${2:-${TMPDIR:-/tmp}/littermap-slam-park}
  shift $(($# > 2 ? 2 : $#))
  run_names=("$@")
}

# simulate_park_run LITTERMAP WORK_DIR RUN: simulates a park run once (cached in WORK_DIR/RUN, with
# any / in RUN as -) and prints that folder, which holds bag/ and truth/. RUN is a world of
# samples/worlds as shipped, WORLD:SEED for another draw of its run (`simulate --run-seed`),
# WORLD@SEED for another park from the same file (`simulate --seed`), WORLD/ROUTE for another of
# its routes (`simulate --route`), or a combination (park_large/perimeter:2, park_tilts@101:2).
simulate_park_run() {
  local littermap=$1 work=$2 run_name=$3
  local world flags=() run_dir
  world=${run_name%%:*}
  if [[ $run_name == *:* ]]; then flags=(--run-seed "${run_name#*:}"); fi
  if [[ $world == *@* ]]; then
    flags+=(--seed "${world#*@}")
    world=${world%%@*}
  fi
  if [[ $world == */* ]]; then flags+=(--route "${world#*/}"); fi
  run_dir=$work/${run_name//\//-}
  if [[ ! -f $run_dir/truth/trajectory.tum ]]; then
    rm -rf "$run_dir"
    mkdir -p "$run_dir"
    "$littermap" -q simulate "$bench_checkout/samples/worlds/${world%%/*}.yaml" -o "$run_dir/bag" \
      --truth "$run_dir/truth" "${flags[@]}" >/dev/null
  fi
  printf '%s\n' "$run_dir"
}

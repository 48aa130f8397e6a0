# shellcheck shell=bash
# Shared by the benchmark scripts (sourced, not run).

# The command prefix that pins a run to one core, when taskset is there.
# shellcheck disable=SC2034  # used by the scripts that source this file
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

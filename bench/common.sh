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

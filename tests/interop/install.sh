#!/usr/bin/env bash
# tests/interop/install.sh DEST: the independent bag readers and writers with their pinned npm
# packages (package-lock.json) in DEST, installed once per lock file; safe to call from tests
# running in parallel.
set -euo pipefail
src=$(cd "$(dirname "$0")" && pwd)
dest=$1
mkdir -p "$dest"
exec 9>"$dest/.lock"
flock 9
cp "$src"/package.json "$src"/package-lock.json "$src"/*.mjs "$dest"/
if ! cmp -s "$src/package-lock.json" "$dest/node_modules/.littermap-lock"; then
  (cd "$dest" && npm ci --no-audit --no-fund --loglevel=error >&2)
  cp "$src/package-lock.json" "$dest/node_modules/.littermap-lock"
fi

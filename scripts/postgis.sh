#!/usr/bin/env bash
# A PostgreSQL 15 + PostGIS 3 server for littermap sites, in a folder, without a system service.
#   scripts/postgis.sh start [DIR] [--port N]   create the cluster on first use, start it, print
#                                               the URL to give littermap (also in DIR/url;
#                                               --port: default a free one, then the same)
#   scripts/postgis.sh stop [DIR]
#   scripts/postgis.sh destroy [DIR]            stop it and delete the cluster (every site in it)
#   scripts/postgis.sh status [DIR]
#   scripts/postgis.sh url [DIR]                the URL of the running server
# DIR defaults to $LITTERMAP_POSTGIS_DIR, else ~/.local/share/littermap/postgis. The server
# listens on localhost only and trusts local logins (anyone on this machine may connect; give
# a shared server passwords, see README). The database is "littermap", owned by the login
# "littermap"; a site is a schema in it:
#   littermap site init "$(scripts/postgis.sh url)?site=north_park" --name "North park"
# PostgreSQL refuses to run as root: root's cluster belongs to the postgres system user.
set -euo pipefail

command=${1:-}
shift || true
dir=${LITTERMAP_POSTGIS_DIR:-$HOME/.local/share/littermap/postgis}
port=
while [[ $# -gt 0 ]]; do
  case $1 in
    --port) port=$2; shift 2 ;;
    -*) echo "postgis.sh: unknown option $1" >&2; exit 2 ;;
    *) dir=$1; shift ;;
  esac
done

bin=/usr/lib/postgresql/15/bin
if [[ ! -x $bin/pg_ctl ]]; then
  echo "postgis.sh: PostgreSQL 15 is not installed (apt-get install postgresql-15" \
       "postgresql-15-postgis-3, or make deps)" >&2
  exit 1
fi
if [[ ! -f /usr/share/postgresql/15/extension/postgis.control ]]; then
  echo "postgis.sh: PostGIS 3 is not installed (apt-get install postgresql-15-postgis-3)" >&2
  exit 1
fi

as_owner=()
if [[ $(id -u) -eq 0 ]]; then
  as_owner=(runuser -u postgres --)
fi
run() { "${as_owner[@]}" "$@"; }

mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
cluster=$dir
if [[ $(id -u) -eq 0 ]]; then
  chown postgres: "$dir"
  # A folder the postgres user cannot reach (under /root, say) keeps only the URL; the cluster
  # goes to a folder of its own under /tmp, named after it.
  if ! runuser -u postgres -- test -w "$dir"; then
    cluster=${TMPDIR:-/tmp}/littermap-postgis-$(printf %s "$dir" | md5sum | cut -c1-12)
    mkdir -p "$cluster"
    chown postgres: "$cluster"
  fi
fi
data=$cluster/data

url() {
  local port
  port=$(sed -n 's/^port = \([0-9]*\).*/\1/p' "$data/postgresql.auto.conf" | tail -1)
  echo "postgresql://littermap@localhost:$port/littermap"
}

running() { [[ -f $data/postmaster.pid ]] && run "$bin/pg_ctl" -D "$data" status >/dev/null 2>&1; }

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

case $command in
  start)
    if running; then
      url | tee "$dir/url"
      exit 0
    fi
    if [[ ! -f $data/PG_VERSION ]]; then
      run "$bin/initdb" -D "$data" -U littermap --auth=trust -E UTF8 --locale=C.UTF-8 \
        >"$cluster/initdb.log"
    fi
    if [[ -z $port ]]; then
      port=$(sed -n 's/^port = \([0-9]*\).*/\1/p' "$data/postgresql.auto.conf" | tail -1)
      [[ -n $port ]] || port=$(free_port)
    fi
    # Settings in postgresql.auto.conf: kept for the next start, read back by `url`.
    sed -i '/^port = /d;/^listen_addresses = /d;/^unix_socket_directories = /d' \
      "$data/postgresql.auto.conf"
    {
      echo "port = $port"
      echo "listen_addresses = 'localhost'"
      echo "unix_socket_directories = '$cluster'"
    } >>"$data/postgresql.auto.conf"
    if ! run "$bin/pg_ctl" -D "$data" -l "$cluster/server.log" -w -t 60 start >/dev/null; then
      echo "postgis.sh: the server did not start; see $cluster/server.log:" >&2
      tail -5 "$cluster/server.log" >&2
      exit 1
    fi
    if ! run "$bin/psql" -h "$cluster" -p "$port" -U littermap -d postgres -Atqc \
        "SELECT 1 FROM pg_database WHERE datname = 'littermap'" | grep -q 1; then
      run "$bin/createdb" -h "$cluster" -p "$port" -U littermap littermap
    fi
    run "$bin/psql" -h "$cluster" -p "$port" -U littermap -d littermap -qc \
      "SET client_min_messages = warning; CREATE EXTENSION IF NOT EXISTS postgis"
    url | tee "$dir/url"
    ;;
  stop)
    if running; then
      run "$bin/pg_ctl" -D "$data" -m fast -w stop >/dev/null
      rm -f "$dir/url"
    fi
    ;;
  destroy)
    if running; then
      run "$bin/pg_ctl" -D "$data" -m fast -w stop >/dev/null
    fi
    rm -rf "$data" "$cluster/initdb.log" "$cluster/server.log" "$dir/url"
    if [[ $cluster != "$dir" ]]; then rmdir "$cluster" 2>/dev/null || true; fi
    ;;
  status)
    if running; then
      echo "running: $(url)"
    else
      echo "stopped ($data)"
      exit 3
    fi
    ;;
  url)
    if ! running; then
      echo "postgis.sh: no server runs in $data; start it with scripts/postgis.sh start" >&2
      exit 1
    fi
    url
    ;;
  *)
    sed -n '2,14s/^# \{0,1\}//p' "$0" >&2
    exit 2
    ;;
esac

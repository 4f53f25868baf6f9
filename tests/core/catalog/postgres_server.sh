#!/usr/bin/env bash
# A throwaway PostgreSQL server for the catalog tests (CTest fixture).
#   postgres_server.sh start DSN_FILE   initdb in a fresh temporary folder,
#       start the server on a Unix socket in it (no TCP port), create the
#       database user `fogbench`, write its address to DSN_FILE as a libpq
#       URI without a database (postgresql://fogbench@/?host=DIR&port=5432;
#       append &dbname=NAME).
#   postgres_server.sh pause DSN_FILE   stop the server, keeping its data (a
#       bench's shared catalog gone offline).
#   postgres_server.sh resume DSN_FILE  start it again on the same data.
#   postgres_server.sh stop DSN_FILE    stop it and remove the folder.
# postgres refuses to run as root: as root, the server runs as `nobody`.
# Fails loudly when the server cannot be had (scripts/setup.sh installs
# postgresql-15); the tests never skip.
set -euo pipefail
what=$1
dsn_file=$2
state_file=$dsn_file.dir

bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1 || true)
if [[ -z $bin || ! -x $bin/initdb ]]; then
  echo "postgres_server.sh: no PostgreSQL server binaries under /usr/lib/postgresql (install postgresql-15: scripts/setup.sh)" >&2
  exit 1
fi
as_server=()
if [[ $(id -u) -eq 0 ]]; then as_server=(runuser -u nobody --); fi

# The server, started on the folder's data and socket.
start_server() {
  "${as_server[@]}" "$bin/pg_ctl" -D "$1/data" -l "$1/server.log" -w -t 60 \
    -o "-k $1 -c listen_addresses='' -c fsync=off -c synchronous_commit=off -c full_page_writes=off" start \
    >/dev/null || { cat "$1/server.log" >&2; exit 1; }
}

case $what in
  start)
    if [[ -f $state_file ]]; then "$0" stop "$dsn_file" || true; fi
    dir=$(mktemp -d /tmp/fogbench-pg.XXXXXX)
    chmod 700 "$dir"
    if [[ $(id -u) -eq 0 ]]; then chown nobody "$dir"; fi
    echo "$dir" > "$state_file"
    "${as_server[@]}" "$bin/initdb" -D "$dir/data" -U fogbench --auth=trust -E UTF8 --no-sync >"$dir/initdb.log" 2>&1 ||
      { cat "$dir/initdb.log" >&2; exit 1; }
    start_server "$dir"
    echo "postgresql://fogbench@/?host=$dir&port=5432" > "$dsn_file"
    echo "postgres_server.sh: PostgreSQL $("$bin/postgres" --version | awk '{print $3}') up on $dir"
    ;;
  pause)
    dir=$(cat "$state_file")
    "${as_server[@]}" "$bin/pg_ctl" -D "$dir/data" -m fast -w stop >/dev/null
    ;;
  resume)
    start_server "$(cat "$state_file")"
    ;;
  stop)
    [[ -f $state_file ]] || exit 0
    dir=$(cat "$state_file")
    "${as_server[@]}" "$bin/pg_ctl" -D "$dir/data" -m fast -w stop >/dev/null 2>&1 || true
    rm -rf "$dir" "$state_file" "$dsn_file"
    ;;
  *) echo "usage: postgres_server.sh start|pause|resume|stop DSN_FILE" >&2; exit 2 ;;
esac

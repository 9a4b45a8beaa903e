#!/usr/bin/env bash
# Runs a command with a throwaway PostgreSQL server on loopback, for the storage tests:
#   bash scripts/postgres-for-tests.sh <command> [args...]
# initdb into a temporary folder, start on a free port, export MICROSIM_TEST_PG_URL
# (postgresql://microsim@127.0.0.1:PORT/microsim), run the command, then stop the server
# and delete the folder, whatever the command's exit status (which this script returns).
# PostgreSQL refuses to run as root, so as root the server runs as the `postgres` user.
set -euo pipefail

bindir=""
for d in /usr/lib/postgresql/*/bin; do
  [ -x "$d/initdb" ] && bindir="$d"
done
if [ -z "$bindir" ]; then
  echo "postgres-for-tests: no PostgreSQL server found (install postgresql)" >&2
  exit 1
fi

as_server=()
if [ "$(id -u)" -eq 0 ]; then
  as_server=(runuser -u postgres --)
fi

dir="$(mktemp -d /tmp/microsim-pg.XXXXXX)"
chmod 755 "$dir"
[ ${#as_server[@]} -gt 0 ] && chown postgres "$dir"


cleanup() {
  "${as_server[@]}" "$bindir/pg_ctl" -D "$dir/data" -m immediate stop >/dev/null 2>&1 || true
  rm -rf "$dir"
}
trap cleanup EXIT

"${as_server[@]}" "$bindir/initdb" -D "$dir/data" -U microsim --auth=trust -E UTF8 --no-locale >"$dir/initdb.log" 2>&1 \
  || { cat "$dir/initdb.log" >&2; exit 1; }
# a free port: a random one that nobody answers on; another program may still take it
# before the server does, so a failed start tries the next
started=0
for attempt in 1 2 3 4 5; do
  port=$((20000 + RANDOM % 40000))
  if (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then continue; fi
  if "${as_server[@]}" "$bindir/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w \
      -o "-c listen_addresses=127.0.0.1 -p $port -k $dir -c fsync=off -c max_connections=200" start >/dev/null; then
    started=1
    break
  fi
done
if [ "$started" -ne 1 ]; then
  cat "$dir/server.log" >&2
  exit 1
fi
"$bindir/createdb" -h 127.0.0.1 -p "$port" -U microsim microsim

export MICROSIM_TEST_PG_URL="postgresql://microsim@127.0.0.1:$port/microsim"
echo "postgres-for-tests: PostgreSQL on 127.0.0.1:$port ($MICROSIM_TEST_PG_URL)"
status=0
"$@" || status=$?
exit "$status"

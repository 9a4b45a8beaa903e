#!/usr/bin/env bash
# README command 1: install, build, and start the app on its embedded default (a SQLite
# history in the user's data folder). Extra arguments go to the app (e.g. --screenshot DIR).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
app="$here/build/${MICROSIM_PRESET:-release}/app/microsim"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "run: no display; starting under xvfb-run (nothing will be visible)" >&2
  exec xvfb-run -a -s "-screen 0 1280x1024x24" "$app" "$@"
fi
exec "$app" "$@"

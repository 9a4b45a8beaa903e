#!/usr/bin/env bash
# README command 2: install what is missing, build the release preset and run the whole suite.
# GUI tests need a display, so the suite runs under xvfb-run, beside a PostgreSQL server that
# scripts/postgres-for-tests.sh starts and stops, so the storage tests run on SQLite and on
# PostgreSQL; ctest prints its summary and fails on any failure. Each stage's time is printed
# at the end (scripts/stage-times.sh). After the whole suite, the Debian package is built from
# the same build and tried from a temporary root (scripts/package-test.sh; MICROSIM_PACKAGE_TEST=0
# leaves it out). CI (.ci/run) runs this, then scripts/hardening.sh. Extra arguments go to ctest
# (e.g. -R Suture, -L gui).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
# shellcheck source=scripts/stage-times.sh
source "$here/scripts/stage-times.sh"
trap 'print_stage_times "scripts/test.sh"' EXIT
preset="${MICROSIM_PRESET:-release}"
timed "install packages" bash "$here/scripts/install-deps.sh"
timed "$preset build" bash "$here/scripts/build.sh"
# a private runtime dir keeps Qt from warning, and test data out of the user's folders
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
# -noreset: Xvfb otherwise resets when its last client leaves, and a GUI test that connects
# during that reset fails with "could not connect to display" (each test is its own process)
timed "$preset suite" bash "$here/scripts/postgres-for-tests.sh" \
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --preset "$preset" "$@"
if [ "${MICROSIM_PACKAGE_TEST:-1}" != 0 ]; then
  timed "$preset package" bash "$here/scripts/package-test.sh" "$here/build/$preset"
fi

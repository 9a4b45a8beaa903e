#!/usr/bin/env bash
# README command 2: install, build, and run every test. GUI tests need a display, so the
# whole suite runs under xvfb-run, beside a PostgreSQL server that scripts/postgres-for-tests.sh
# starts and stops; ctest prints its summary and fails on any failure. Then the hardening
# stages (scripts/hardening.sh): the suite under ASan+UBSan, the fuzzers for a bounded time,
# the threaded suites under TSan and clang-tidy. MICROSIM_SKIP_HARDENING=1 stops after the
# release suite (a quicker check while working; CI never sets it).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
cd "$here"
preset="${MICROSIM_PRESET:-release}"
# a private runtime dir keeps Qt from warning, and test data out of the user's folders
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
# the storage tests also run against a throwaway PostgreSQL server on loopback
# -noreset: Xvfb otherwise resets when its last client leaves, and a GUI test that connects
# during that reset fails with "could not connect to display" (each test is its own process)
bash "$here/scripts/postgres-for-tests.sh" \
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --preset "$preset" "$@"
if [ "${MICROSIM_SKIP_HARDENING:-0}" != 1 ]; then
  bash "$here/scripts/hardening.sh"
fi

#!/usr/bin/env bash
# Repeats the README's cold CI measurement: a fresh clone of this checkout's HEAD, ccache and
# every XDG cache (the clang-tidy cache among them) pointed at empty folders, then `bash .ci/run`
# with its per-stage times (scripts/stage-times.sh) and the wall clock of the whole. Packages are
# not removed: on a machine without them, "install packages" adds the apt time (README).
#   scripts/measure-cold-ci.sh [WORK_DIR]      (default: a new folder under /tmp; kept, with the log)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${1:-$(mktemp -d /tmp/microsim-cold-ci.XXXXXX)}"
mkdir -p "$work"
rm -rf "$work/clone" "$work/ccache" "$work/cache"
git clone -q "$here" "$work/clone"
mkdir -p "$work/ccache" "$work/cache"
export CCACHE_DIR="$work/ccache" XDG_CACHE_HOME="$work/cache"
unset MICROSIM_STAGE_TIMES
echo "measure-cold-ci: $(git -C "$work/clone" log -1 --format='%h %s') in $work/clone, nothing cached"
start=$SECONDS
status=0
(cd "$work/clone" && CI=true bash .ci/run </dev/null) >"$work/ci.log" 2>&1 || status=$?
elapsed=$((SECONDS - start))
sed -n '/^stage times (.ci\/run):/,$p' "$work/ci.log"
grep -E '^(100% tests passed|[0-9]+% tests passed|tidy: [0-9]+ files)' "$work/ci.log" || true
printf 'measure-cold-ci: .ci/run exited %d after %d min %02d s; the log is %s\n' \
  "$status" $((elapsed / 60)) $((elapsed % 60)) "$work/ci.log"
exit "$status"

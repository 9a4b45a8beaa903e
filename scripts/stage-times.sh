#!/usr/bin/env bash
# Sourced by scripts/test.sh and scripts/hardening.sh: each stage of the test command is run
# through `timed NAME COMMAND...`, which appends "NAME<TAB>SECONDS" to $MICROSIM_STAGE_TIMES,
# and `print_stage_times` prints them as the table the README keeps (scripts/measure-cold-ci.sh
# repeats that measurement with nothing cached). The first script that sources this file
# owns the list and prints it; a script it calls appends to the same list and prints nothing.
stage_times_owner=0
if [ -z "${MICROSIM_STAGE_TIMES:-}" ]; then
  MICROSIM_STAGE_TIMES="$(mktemp /tmp/microsim-stage-times.XXXXXX)"
  export MICROSIM_STAGE_TIMES
  stage_times_owner=1
fi

timed() {
  local name="$1"
  shift
  printf '\n== %s (%s)\n' "$name" "$(date +%H:%M:%S)"
  local start=$SECONDS status=0
  "$@" || status=$?
  printf '%s\t%d\n' "$name" $((SECONDS - start)) >>"$MICROSIM_STAGE_TIMES"
  return "$status"
}

print_stage_times() {
  [ "$stage_times_owner" = 1 ] || return 0
  local total=0 name seconds
  printf '\nstage times (%s):\n' "$1"
  while IFS=$'\t' read -r name seconds; do
    printf '  %-34s %3d min %02d s\n' "$name" $((seconds / 60)) $((seconds % 60))
    total=$((total + seconds))
  done <"$MICROSIM_STAGE_TIMES"
  printf '  %-34s %3d min %02d s\n' "total" $((total / 60)) $((total % 60))
  # kept beside the caches, so the next session on this machine can read what CI's stages took
  # (a passing CI run's output is not kept anywhere else)
  local log="${XDG_CACHE_HOME:-$HOME/.cache}/microsim/stage-times.log"
  if mkdir -p "$(dirname "$log")" 2>/dev/null; then
    {
      printf '%s %s %s\n' "$(date -u +%FT%TZ)" "$1" "$(git rev-parse --short HEAD 2>/dev/null || echo '?')"
      sed 's/^/  /' "$MICROSIM_STAGE_TIMES"
      printf '  total\t%d\n' "$total"
    } >>"$log" 2>/dev/null || true
  fi
  rm -f "$MICROSIM_STAGE_TIMES"
}

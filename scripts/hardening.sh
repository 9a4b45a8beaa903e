#!/usr/bin/env bash
# The hardening stages (issue #10) that CI (.ci/run) runs after the README's test command:
#   1. one clang-14 build with AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer
#      coverage (preset "sanitize"): the WHOLE test suite runs on it, under Xvfb, beside a
#      throwaway PostgreSQL server, exactly as the release suite does;
#   2. the same build's libFuzzer targets, each for MICROSIM_FUZZ_SECONDS (default 20) from its
#      seed corpus in tests/fuzz/corpus/; a crash, leak, timeout or broken property fails the
#      run and leaves the input in build/sanitize/fuzz-artifacts/ (add it to the corpus as a
#      regression seed once fixed);
#   3. a ThreadSanitizer build (preset "tsan", clang-14, build/tsan) of the suites whose objects
#      cross threads: the simulation thread (runner, viewport, the attempt page's scoring), the
#      tracker client's thread and the GUI thread; under Xvfb, stopping at the first report
#      (tests/sanitizers/tsan.supp says how it stays clean without suppressions);
#   4. clang-tidy over every first-party translation unit (scripts/tidy.sh), which must report
#      nothing; units recorded clean in scripts/tidy-verified.txt and unchanged since are not
#      analysed again.
# The instrumented builds are unity builds with line tables only (CMakePresets.json), and each
# stage's time is printed at the end (scripts/stage-times.sh).
# Usage: scripts/hardening.sh [sanitize|fuzz|tsan|tidy ...]   (default: all four, in that order)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
# shellcheck source=scripts/ccache-env.sh
source "$here/scripts/ccache-env.sh"
# shellcheck source=scripts/stage-times.sh
source "$here/scripts/stage-times.sh"
trap 'print_stage_times "scripts/hardening.sh"' EXIT
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
# symbolised stacks in every sanitizer report
export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-/usr/bin/llvm-symbolizer-14}"
jobs="$(nproc)"
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(sanitize fuzz tsan tidy)

# -noreset: see scripts/test.sh
under_display_and_postgres() {
  bash "$here/scripts/postgres-for-tests.sh" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
}

# (each stage runs inside `timed ... ||`, where bash ignores set -e: chain with &&)
build_sanitize() {
  cmake --preset sanitize >/dev/null && cmake --build --preset sanitize -j "$jobs"
}

run_sanitize() {
  timed "ASan+UBSan build" build_sanitize
  timed "ASan+UBSan suite" under_display_and_postgres ctest --preset sanitize
}

run_fuzz() {
  [ -x build/sanitize/tests/fuzz/microsim_fuzz_scene ] || build_sanitize || return 1
  local seconds="${MICROSIM_FUZZ_SECONDS:-20}"
  local artifacts="$here/build/sanitize/fuzz-artifacts"
  mkdir -p "$artifacts"
  echo "each fuzz target for ${seconds} s"
  local failed=()
  for seeds in tests/fuzz/corpus/*/; do
    local name
    name="$(basename "$seeds")"
    local fuzzer="build/sanitize/tests/fuzz/microsim_fuzz_$name"
    # new inputs go to a scratch folder; the tree's corpus stays as committed
    local scratch
    scratch="$(mktemp -d)"
    if "$fuzzer" "$scratch" "$seeds" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 \
        -print_final_stats=1 -artifact_prefix="$artifacts/$name-" >"$artifacts/$name.log" 2>&1; then
      printf '  %-14s %s\n' "$name" "$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' \
        "$artifacts/$name.log" | grep -o '[0-9]*$') inputs, clean"
    else
      failed+=("$name")
      echo "  $name: FAILED; the log and the input are in $artifacts" >&2
      tail -n 40 "$artifacts/$name.log" >&2
    fi
    rm -rf "$scratch"
  done
  [ ${#failed[@]} -eq 0 ] || { echo "hardening: fuzz targets failed: ${failed[*]}" >&2; return 1; }
}

build_tsan() {
  cmake --preset tsan >/dev/null && cmake --build --preset tsan -j "$jobs"
}

run_tsan() {
  timed "TSan build" build_tsan
  timed "TSan suite" under_display_and_postgres ctest --preset tsan
}

for stage in "${stages[@]}"; do
  case "$stage" in
    sanitize) run_sanitize ;;
    fuzz) timed "fuzzers" run_fuzz ;;
    tsan) run_tsan ;;
    tidy) timed "clang-tidy" bash "$here/scripts/tidy.sh" "$here/build/release" ;;
    *) echo "hardening: unknown stage '$stage' (sanitize, fuzz, tsan, tidy)" >&2; exit 2 ;;
  esac
done
echo "hardening: all stages passed: ${stages[*]}"

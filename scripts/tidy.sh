#!/usr/bin/env bash
# Runs clang-tidy-14 with the project's .clang-tidy over every first-party translation unit
# (sim/, assessment/, app/, tests/) of BUILD_DIR's compile_commands.json, two at a time, and
# fails with the diagnostics printed if any is reported.
#
#   scripts/tidy.sh [--record] [BUILD_DIR]        (default: build/release, the README's build)
#
# scripts/tidy.py does the work and says how a unit is keyed. A unit is analysed unless its
# key is known clean: in the local cache (${XDG_CACHE_HOME:-$HOME/.cache}/microsim/tidy/) or
# in the committed record scripts/tidy-verified.txt, so a machine with nothing cached
# analyses only what changed since the recorded run. --record rewrites that record after a
# run that found nothing: run it before committing when the stage analysed many files.
# Needs the packages clang-tidy-14 and clang-14; the build dir must have been built (or at
# least its *_autogen targets), which this script does if generated sources are missing.
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
record=()
if [ "${1:-}" = --record ]; then
  record=(--record)
  shift
fi
build="${1:-$src/build/release}"
if [ ! -d "$build" ]; then
  echo "tidy: build dir $build does not exist; configure and build it first" >&2
  exit 2
fi
build="$(cd "$build" && pwd)"

# the compile database is opt-in in CMake: turn it on for this build dir if it is off
if [ ! -f "$build/compile_commands.json" ]; then
  cmake -S "$src" -B "$build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
fi
# sources added since the last build are only in the database once CMake re-globbed
if [ -f "$build/build.ninja" ]; then
  ninja -C "$build" build.ninja >/dev/null
fi
# moc/uic output is included by our sources: generate it if this build dir never was built
# (the *_autogen targets first build the libraries their target links, so only when missing)
if [ -f "$build/build.ninja" ] && ! compgen -G "$build/app/*_autogen/include" >/dev/null; then
  mapfile -t autogen < <(ninja -C "$build" -t targets all 2>/dev/null |
    sed -n 's/^\([A-Za-z0-9_.-]*_autogen\): phony$/\1/p' | sort -u)
  if [ ${#autogen[@]} -gt 0 ]; then
    cmake --build "$build" -j 2 --target "${autogen[@]}" >/dev/null
  fi
fi

cache="${XDG_CACHE_HOME:-$HOME/.cache}/microsim/tidy"
exec python3 "$src/scripts/tidy.py" --src "$src" --build "$build" --cache "$cache" \
  --verified "$src/scripts/tidy-verified.txt" "${record[@]}"

#!/usr/bin/env bash
# The Debian package, built and tried as a user would get it: `cpack -G DEB` in a build dir
# (default build/release, already built), the package's files and fields checked, then
# unpacked with dpkg-deb into a temporary root (no root needed, nothing outside it touched)
# and run from there: `microsim-cli --version`, a replay and a scored replay of the installed
# recording on the installed scene and rubric (state hash and score against
# tests/support/golden_stitch.h, the attempt stored in an SQLite history), and the installed
# app started under Xvfb (`microsim --check-start`: the window drawn, every installed lesson
# read). scripts/test.sh runs it after the suite.
#   bash scripts/package-test.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$here/build/release}" && pwd)"

fail() {
  echo "package-test: $*" >&2
  exit 1
}

# ---- build the package (cpack first brings the build up to date)
out="$build/package"
rm -rf "$out"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" >"$out.log" 2>&1 || {
  cat "$out.log" >&2
  fail "cpack failed"
}
debs=("$out"/microsim_*.deb)
if [ ${#debs[@]} -ne 1 ] || [ ! -f "${debs[0]}" ]; then fail "expected one microsim_*.deb in $out"; fi
deb="${debs[0]}"
echo "package-test: built $deb ($(du -h "$deb" | cut -f1))"

# ---- its fields: name, version (the project's, Debian revision 1), derived dependencies
field() { dpkg-deb --field "$deb" "$1"; }
project_version="$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")"
[ "$(field Package)" = microsim ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$project_version-1" ] || fail "Version is '$(field Version)', not $project_version-1"
[ "$(field Section)" = education ] || fail "Section is '$(field Section)'"
[ "$(field Suggests)" = spacenavd ] || fail "Suggests is '$(field Suggests)', not spacenavd (the 3D mouse's daemon)"
depends="$(field Depends)"
for lib in libqt6widgets6 libqt6sql6 libqt6sql6-sqlite libassimp5 libopenigtlink1.11 libsdl2-2.0-0 libspnav0 libosdcpu3.5.0; do
  [[ ", $depends," == *", $lib "* || ", $depends," == *", $lib,"* ]] || fail "Depends lacks $lib: $depends"
done

# every dependency is met on this machine (which has what the build needs), checked against
# dpkg's database without installing anything
IFS=',' read -ra clauses <<<"$depends"
for clause in "${clauses[@]}"; do
  met=0
  IFS='|' read -ra alternatives <<<"$clause"
  for alternative in "${alternatives[@]}"; do
    read -r name constraint <<<"$alternative"
    name="${name%%:*}"
    installed="$(dpkg-query -W -f='${db:Status-Status} ${Version}' "$name" 2>/dev/null || true)"
    [ "${installed%% *}" = installed ] || continue
    if [ -z "$constraint" ]; then
      met=1
    else
      read -r op version <<<"${constraint//[()]/ }"
      case "$op" in ">=") op=ge ;; "<=") op=le ;; ">>") op=gt ;; "<<") op=lt ;; "=") op=eq ;; esac
      dpkg --compare-versions "${installed#* }" "$op" "$version" && met=1
    fi
    [ "$met" = 1 ] && break
  done
  [ "$met" = 1 ] || fail "dependency not met here:$clause"
done

# ---- its files: the Debian layout, every shipped resource, no shaders (compiled in)
contents="$(dpkg-deb --contents "$deb" | awk '{print $NF}')"
expect=(
  ./usr/bin/microsim ./usr/bin/microsim-cli
  ./usr/share/applications/microsim.desktop
  ./usr/share/icons/hicolor/scalable/apps/microsim.svg
  ./usr/share/man/man1/microsim.1.gz ./usr/share/man/man1/microsim-cli.1.gz
  ./usr/share/doc/microsim/copyright
)
while IFS= read -r shipped; do
  expect+=("./usr/share/microsim/${shipped#"$here/resources/"}")
done < <(find "$here/resources" -type f ! -path '*/shaders/*' | sort)
for path in "${expect[@]}"; do
  grep -qxF "$path" <<<"$contents" || fail "the package lacks $path"
done
! grep -q '/shaders/' <<<"$contents" || fail "the package holds the shaders, which are compiled into the app"

# ---- unpack into a temporary root, as dpkg would install it under /
root="$(mktemp -d /tmp/microsim-package-test.XXXXXX)"
trap 'rm -rf "$root"' EXIT
dpkg-deb --extract "$deb" "$root/fs"
bin="$root/fs/usr/bin"
share="$root/fs/usr/share/microsim"
for program in microsim microsim-cli; do
  sections="$(readelf -S "$bin/$program")"
  ! grep -q '\.symtab' <<<"$sections" || fail "the installed $program is not stripped"
done
desktop-file-validate "$root/fs/usr/share/applications/microsim.desktop" || fail "the desktop entry is invalid"
for page in microsim microsim-cli; do
  warnings="$(gunzip -c "$root/fs/usr/share/man/man1/$page.1.gz" | groff -man -ww -z -Tutf8 2>&1)"
  [ -z "$warnings" ] || fail "groff warns about $page.1: $warnings"
done

# ---- the installed programs, with settings, data and runtime files in the temporary root
export HOME="$root/home" XDG_CONFIG_HOME="$root/home/config" XDG_DATA_HOME="$root/home/data"
export XDG_RUNTIME_DIR="$root/runtime" LC_ALL=C LANG=C
mkdir -p "$HOME" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
unset MICROSIM_RESOURCES

version="$("$bin/microsim-cli" --version)"
[ "$version" = "microsim-cli $project_version" ] || fail "--version says '$version'"

golden() { sed -n "s/.*$1 = \"\{0,1\}\([0-9a-f.]*\)\"\{0,1\};.*/\1/p" "$here/tests/support/golden_stitch.h"; }
"$bin/microsim-cli" run --scene "$share/scenes/anastomosis.json" --input "$share/recordings/stitch.msrec" \
  --json "$root/run.json" >"$root/run.txt" || fail "the installed replay failed: $(cat "$root/run.txt")"
grep -q "\"$(golden kGoldenStitchHashText)\"" "$root/run.json" ||
  fail "the installed replay's state hash is not the golden one: $(grep -o '"hash"[^,]*' "$root/run.json")"

"$bin/microsim-cli" score --recording "$share/recordings/stitch.msrec" \
  --rubric "$share/rubrics/03_single_stitch.json" --scene "$share/scenes/anastomosis.json" \
  --db "$root/history.sqlite" --trainee "Package Test" --json "$root/score.json" >"$root/score.txt" ||
  fail "the installed score failed: $(cat "$root/score.txt")"
score="$(grep -o '"score": *[0-9.]*' "$root/score.json" | head -1 | sed 's/.*: *//')"
awk -v a="$score" -v b="$(golden kGoldenStitchScoreSingleStitch)" 'BEGIN { exit !(a - b < 1e-9 && b - a < 1e-9) }' ||
  fail "the installed score is $score, not $(golden kGoldenStitchScoreSingleStitch)"
trainees="$("$bin/microsim-cli" db list-trainees --db "$root/history.sqlite")"
grep -q "Package Test" <<<"$trainees" || fail "the scored attempt's trainee is not in the installed history: $trainees"
echo "package-test: $version replayed the installed stitch (golden hash) and scored it $score"

started="$(xvfb-run -a -s "-screen 0 1280x1024x24" "$bin/microsim" --check-start --database "$root/app.sqlite")" ||
  fail "the installed app did not start"
[[ "$started" == *"from $share/lessons,"* ]] || fail "the installed app read its lessons elsewhere: $started"
echo "package-test: $started"
echo "package-test: passed"

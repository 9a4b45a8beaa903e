#!/usr/bin/env bash
# Installs every Debian package that microsim's build, tests and benchmarks need.
# Idempotent: packages already present are skipped, and apt is not touched at all
# when nothing is missing. Works as root, or through sudo for an ordinary user.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git ccache
  # engine
  libeigen3-dev nlohmann-json3-dev libassimp-dev libfcl-dev
  # the drawn tissue's smooth surface (Loop subdivision)
  libosd-dev
  # benchmark peers (tests/bench, never linked by the engine): Bullet's soft body
  libbullet-dev
  # Qt 6: widgets, OpenGL, SQL (SQLite and PostgreSQL drivers), charts, network, translations
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libqt6sql6-sqlite libqt6sql6-psql qt6-charts-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools linguist-qt6 qt6-svg-dev qt6-translations-l10n
  libgl1-mesa-dev libgl1-mesa-dri libglx-mesa0
  # trackers, and the 6-DoF devices people own: 3D mice (libspnav; the user runs spacenavd) and
  # game controllers (SDL2)
  libopenigtlink-dev libspnav-dev libsdl2-dev
  # tests: GoogleTest, a virtual display for GUI tests, a PostgreSQL server for the storage tests
  libgtest-dev libgmock-dev xvfb xauth postgresql
  # the Debian package (scripts/package-test.sh): cpack's dependency derivation (dpkg-shlibdeps),
  # the desktop entry's validator, groff to check the man pages
  dpkg-dev desktop-file-utils groff-base
  # hardening (scripts/hardening.sh): clang with its sanitizer and libFuzzer runtimes, the
  # symbolizer for their stack traces, clang-tidy
  clang-14 libclang-rt-14-dev llvm-14 clang-tidy-14
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"

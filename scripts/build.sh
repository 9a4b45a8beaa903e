#!/usr/bin/env bash
# Installs what is missing, then configures and builds microsim (preset "release"
# unless MICROSIM_PRESET says otherwise). Idempotent: a second run only rebuilds.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash scripts/install-deps.sh
# shellcheck source=scripts/ccache-env.sh
source scripts/ccache-env.sh
preset="${MICROSIM_PRESET:-release}"
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"

# Sourced by the build scripts. ccache (when installed) shares compiled objects between build
# trees and between clones: paths under the source tree are rewritten relative to the build
# dir, and the build dir itself is left out of the hash, so a fresh clone anywhere on the
# machine reuses what an earlier one compiled. Objects whose command line names the source
# dir itself (e.g. the tests' data-path defines) are still compiled per clone, as they must be.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
export CCACHE_NOHASHDIR=1

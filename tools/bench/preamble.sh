# The start every benchmark script shares: from the repository root, install the missing Debian
# packages (tools/install-deps), configure the release preset if no build is configured, and
# build the targets the script names. Sourced, not run:
#   source "$(dirname "$0")/preamble.sh" TARGET...
# Leaves `build` (GROWTHUQ_BUILD_DIR if set and configured, else build/release), `cli`
# ($build/growthuq) and `bench_bin` ($build/tools/bench, where the benchmark executables are).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."

tools/install-deps
build=${GROWTHUQ_BUILD_DIR:-build/release}
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake --preset release >/dev/null
  build=build/release
fi
if (($#)); then
  cmake --build "$build" --target "$@" >/dev/null
fi
cli="$build/growthuq"
bench_bin="$build/tools/bench"
if [[ $(id -u) == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi

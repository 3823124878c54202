#!/usr/bin/env bash
# Installs the Debian packages hexray needs, then configures and builds it in build/.
# Arguments go to ci/install-deps.sh: `--render` installs and builds only the `hexray` executable
# (ci/render-demo.sh: the first picture); `--bench` also installs the bench report's optional
# packages. HEXRAY_WERROR=ON (as CI sets it) turns the compiler's warnings into errors.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/install-deps.sh "$@"
testing=ON
targets=()
if [ "${1:-}" = --render ]; then
  testing=OFF
  targets=(--target hexray)
fi
bash ci/configure.sh release -DHEXRAY_WERROR="${HEXRAY_WERROR:-OFF}" -DBUILD_TESTING="$testing"
cmake --build --preset release --parallel "$(nproc)" "${targets[@]}"

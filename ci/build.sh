#!/usr/bin/env bash
# Installs the Debian packages hexray needs, then configures and builds it in build/.
# Arguments go to ci/install-deps.sh (`--bench`: also the bench report's optional packages).
# HEXRAY_WERROR=ON (as CI sets it) turns the compiler's warnings into errors.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/install-deps.sh "$@"
cmake --preset release -DHEXRAY_WERROR="${HEXRAY_WERROR:-OFF}"
cmake --build --preset release --parallel "$(nproc)"

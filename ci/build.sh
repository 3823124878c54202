#!/usr/bin/env bash
# Installs the Debian packages hexray needs, then configures and builds it in build/.
# Arguments go to ci/install-deps.sh (`--bench`: also the bench report's optional packages).
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/install-deps.sh "$@"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"

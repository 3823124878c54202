#!/usr/bin/env bash
# From a fresh clone: install, build, and render the default scene to lecture-demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh
./build/hexray render scenes/lecture-demo.json -o lecture-demo.png

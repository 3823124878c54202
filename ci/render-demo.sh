#!/usr/bin/env bash
# From a fresh clone: install what building and running hexray needs, build the executable only,
# and render the default scene to lecture-demo.png. (ci/test.sh installs and builds everything.)
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh --render
./build/hexray render scenes/lecture-demo.json -o lecture-demo.png

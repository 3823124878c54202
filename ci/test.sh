#!/usr/bin/env bash
# From a fresh clone: install, build, and run every test (GPU tests on lavapipe, under the
# Khronos validation layer). This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh
echo "--- Vulkan devices"
./build/hexray devices
echo "--- tests"
ctest --test-dir build --output-on-failure --parallel "$(nproc)"

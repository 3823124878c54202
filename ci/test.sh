#!/usr/bin/env bash
# From a fresh clone: install, build, and run every test (GPU tests on lavapipe, under the
# Khronos validation layer). This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh
# The GPU tests and goldens are lavapipe's: use it even where a real GPU is present.
lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
echo "--- Vulkan devices"
./build/hexray devices
echo "--- tests"
ctest --test-dir build --output-on-failure --parallel "$(nproc)"

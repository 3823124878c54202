#!/usr/bin/env bash
# From a fresh clone: install, build, and run every test (GPU tests on lavapipe, under the
# Khronos validation layer); then the same tests built with ASan and UBSan; then fuzz the
# scene loader for 60 s and both renderers against each other for 120 s. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

timings=()
timed() {  # runs a step and notes how long it took
  local name=$1 start=$SECONDS
  shift
  echo "=== $name"
  "$@"
  timings+=("$name: $((SECONDS - start)) s")
}

tests() {
  # The GPU tests and goldens are lavapipe's: use it even where a real GPU is present.
  local lavapipe_icd
  lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
  VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd" ./build/hexray devices
  VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd" \
    ctest --test-dir build --output-on-failure --parallel "$(nproc)"
}

timed "install and build" bash ci/build.sh
timed "tests" tests
timed "sanitizer build and tests" bash ci/sanitize.sh
timed "fuzzing the scene loader" bash ci/fuzz.sh 60
timed "differential fuzzing" bash ci/fuzz.sh --differential 120
printf '%s\n' "=== times" "${timings[@]}"

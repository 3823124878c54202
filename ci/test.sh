#!/usr/bin/env bash
# From a fresh clone: install, build with warnings as errors, check the style, and run every test
# (GPU tests on lavapipe, under the Khronos validation layer); then the command-line tests built
# with ASan and UBSan; then fuzz the readers of untrusted files for 40 s and both renderers
# against each other for 80 s. This is what CI runs.
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
  # CTest runs the tests on lavapipe (tests/CMakeLists.txt, HEXRAY_TEST_VULKAN_DRIVER).
  ctest --test-dir build --output-on-failure --parallel "$(nproc)"
}

timed "install and build (warnings are errors)" env HEXRAY_WERROR=ON bash ci/build.sh
timed "style (clang-format, function size, clang-tidy)" bash ci/lint.sh
timed "tests" tests
timed "sanitizer build and command-line tests" bash ci/sanitize.sh
timed "fuzzing the readers of untrusted files" bash ci/fuzz.sh 40
timed "differential fuzzing" bash ci/fuzz.sh --differential 80
printf '%s\n' "=== times" "${timings[@]}"

#!/usr/bin/env bash
# Builds hexray and its tests with AddressSanitizer and UndefinedBehaviorSanitizer in
# build-asan/ and runs every test there (GPU tests on lavapipe; Mesa and the Vulkan loader
# are not instrumented, hexray's host code is). Any sanitizer report fails. Needs the
# packages from ci/install-deps.sh; ci/test.sh runs it after the normal build and tests.
set -euo pipefail
cd "$(dirname "$0")/.."

# halt_on_error/abort: a report ends the process with an error even where a test expects a
# nonzero exit code (the CLI tests), and the sanitizer's message is in the test output.
# verify_asan_link_order=0: the dlclose shim below is preloaded ahead of the ASan runtime.
export ASAN_OPTIONS="abort_on_error=1:halt_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:verify_asan_link_order=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/ci/lsan.supp:print_suppressions=0"

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake --build build-asan --parallel "$(nproc)"

cc -shared -fPIC -O1 -o build-asan/keep-libraries-loaded.so ci/keep-libraries-loaded.c
export LD_PRELOAD="$PWD/build-asan/keep-libraries-loaded.so"

lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"

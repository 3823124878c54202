#!/usr/bin/env bash
# Builds the hexray executable with AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/
# and runs the release build's command-line tests against it (HEXRAY_UNDER_TEST): the executable
# as users run it (every subcommand, bad inputs, faults, signals, outputs), GPU work on lavapipe
# (Mesa and the Vulkan loader are not instrumented, hexray's host code is). Any sanitizer report
# fails. The tests only start the executable, so they need no instrumenting themselves.
# The readers of untrusted files are fuzzed under the same sanitizers (ci/fuzz.sh); the unit and
# GPU tests run in the release build. Needs the packages from ci/install-deps.sh and the release
# build's tests (build/tests/hexray_cli_tests); ci/test.sh runs it after the normal build and tests.
set -euo pipefail
cd "$(dirname "$0")/.."

# halt_on_error/abort: a report ends the process with an error even where a test expects a
# nonzero exit code (the CLI tests), and the sanitizer's message is in the test output.
# verify_asan_link_order=0: the dlclose shim below is preloaded ahead of the ASan runtime.
export ASAN_OPTIONS="abort_on_error=1:halt_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:verify_asan_link_order=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/ci/lsan.supp:print_suppressions=0"

# The flags are CMakePresets.json's "asan" (-g1: line tables, all a report's stack needs).
bash ci/configure.sh asan
cmake --build --preset asan --parallel "$(nproc)" --target hexray
export HEXRAY_UNDER_TEST="$PWD/build-asan/hexray"

cc -shared -fPIC -O1 -o build-asan/keep-libraries-loaded.so ci/keep-libraries-loaded.c
export LD_PRELOAD="$PWD/build-asan/keep-libraries-loaded.so"
export VK_DRIVER_FILES
VK_DRIVER_FILES=$(sed -n 's/^HEXRAY_TEST_VULKAN_DRIVER:STRING=//p' build-asan/CMakeCache.txt)

# Tests that repeat the same code over many scenes or frames, or check what an output says rather
# than how it is written (the compare gate over the whole scene tree, the JSON documents, the bench,
# the report in headless chromium, which is not instrumented): they run in the release build.
repeated="ProgressCliTest.RenderShowsRowsDoneAndTimeLeftOnATerminalOnBothBackends"
repeated+=":CliTest.ABatchOfMoreScenesThanTheRendererKeepsKernelsForGivesEachTheImageItGetsAlone"
repeated+=":CliTest.CompareAllPrintsOneTableOfScenesAndPrecisions"
repeated+=":StripCliTest.MergedGpuStripsWithCullingAreTheSingleRenderPixelForPixel"
repeated+=":CompareGateCliTest.TheShippedScenes*:CompareGateCliTest.ANearTiedScene*:CompareGateCliTest.CommandLine*"
repeated+=":CompareGateCliTest.AnExpectationThatNoLongerHolds*:CompareGateCliTest.MeanFlip*"
repeated+=":ReportTest.EveryImageLoads*:ReportTest.AMissingImage*:ReportTest.TheGpuRenderFlips*"
repeated+=":ReportTest.AFailedScene*:ReportTest.AMissingBrowser*"
repeated+=":JsonCliTest.Render*:JsonCliTest.Pixel*:BenchCliTest.*"
# AddressSanitizer reserves terabytes of address space: the memory tests' ulimit -v cannot apply.
repeated+=":MemoryCliTest.*"

# One process per core, each a shard of the tests (GoogleTest's own sharding).
shards=$(nproc)
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
pids=()
for ((shard = 0; shard < shards; shard++)); do
  GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
    build/tests/hexray_cli_tests --gtest_filter="-$repeated" --gtest_brief=1 >"$logs/$shard" 2>&1 &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
cat "$logs"/*
exit "$status"

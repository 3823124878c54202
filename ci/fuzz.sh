#!/usr/bin/env bash
# Builds the fuzzers (clang-14, libFuzzer, ASan, UBSan) in build-fuzz/ and fuzzes for a fixed time
# in all (default 60 s; bash ci/fuzz.sh SECONDS): half for the scene loader, from the shipped scenes
# and tests/fuzz/regressions/, a quarter each for merge's piece reader, from the PNG and OpenEXR
# pieces in tests/fuzz/pieces/, and for the kernel cache's reader, from tests/fuzz/kernel_cache_seeds/.
# Fails on any crash, hang, leak, sanitizer report or broken
# invariant; the input that caused it is written to build-fuzz/artifacts/.
#
# bash ci/fuzz.sh --differential SECONDS: instead, the differential fuzzer (generated valid scenes
# through the GPU in every precision and the CPU reference, judged as `hexray compare` judges) on
# lavapipe from the normal build in build/; shrunk failing scenes go to build/differential-failures/.
# Its seeds start at HEXRAY_DIFFERENTIAL_FIRST_SEED, else at one taken from the commit, so that each
# commit explores scenes of its own and the same commit the same ones; it prints the range covered,
# and `build/tests/hexray_differential_fuzzer --seed N` replays one.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --differential ]; then
  bash ci/configure.sh release >/dev/null
  cmake --build --preset release --parallel "$(nproc)" --target hexray_differential_fuzzer >/dev/null
  lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
  export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
  # One process a core, each on every jobs-th seed, each with one lavapipe thread: a 32 x 24 image
  # gains nothing from more, and the hand-over between threads costs a third of a scene's time.
  export LP_NUM_THREADS=1
  commit=$(git rev-parse --short=7 HEAD 2>/dev/null || echo 0)
  first_seed=${HEXRAY_DIFFERENTIAL_FIRST_SEED:-$((0x$commit * 1000))}
  jobs=$(nproc)
  logs=$(mktemp -d)
  trap 'rm -rf "$logs"' EXIT
  pids=()
  for ((job = 0; job < jobs; job++)); do
    build/tests/hexray_differential_fuzzer --seconds "${2:-120}" --first-seed $((first_seed + job)) \
      --seed-stride "$jobs" --failures build/differential-failures >"$logs/$job" 2>&1 &
    pids+=($!)
  done
  status=0
  for pid in "${pids[@]}"; do wait "$pid" || status=1; done
  cat "$logs"/*
  # The whole run from the processes' summaries: "N scenes (...) in T s: ...; F failed; ...".
  awk -v first="$first_seed" -v jobs="$jobs" '/ scenes \(seeds / {
      n += $1
      least = (least == "" || $1 < least) ? $1 : least
      for (i = 1; i < NF; i++) {
        if ($i == "in" && $(i + 2) == "s:" && $(i + 1) > t) t = $(i + 1)
        if ($(i + 1) == "failed;") f += $i
      } }
    END { printf "in all: %d scenes from seed %.0f (every seed to %.0f) in %.0f s: %.1f scenes per second; %d failed\n",
          n, first, first + least * jobs - 1, t, n / t, f }' "$logs"/*
  exit "$status"
fi
seconds=${1:-60}
piece_seconds=$((seconds / 4))
cache_seconds=$((seconds / 4))
scene_seconds=$((seconds - piece_seconds - cache_seconds))

bash ci/configure.sh fuzz
cmake --build --preset fuzz --parallel "$(nproc)"

# New inputs go to scratch corpora; the seed folders are only read. Scene inputs are capped at
# 4 KiB, above every shipped scene, so mutations stay cheap (the 20 KB deep-nesting seed is cut).
rm -rf build-fuzz/corpus build-fuzz/corpus-pieces build-fuzz/kernel-cache-corpus build-fuzz/artifacts
mkdir -p build-fuzz/corpus build-fuzz/corpus-pieces build-fuzz/kernel-cache-corpus build-fuzz/artifacts
# sed drops progress lines and libFuzzer's dictionary suggestions (stats and any report stay);
# pipefail keeps the fuzzer's exit status.
quiet() {
  sed -e '/^#[0-9]/d' -e '/^INFO: /d' -e '/^	NEW_FUNC/d' -e '/^###### Recommended/,/^###### End of recommended/d'
}
build-fuzz/tests/fuzz/scene_loader_fuzzer build-fuzz/corpus scenes tests/fuzz/regressions \
  -dict=tests/fuzz/scene.dict -max_len=4096 -max_total_time="$scene_seconds" -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ 2>&1 | quiet
# No single allocation above 64 MiB: a valid piece needs at most a band of 64 rows of 16384 pixels
# (12 MiB), so a larger one was sized from a field nothing checked.
build-fuzz/tests/fuzz/strip_piece_fuzzer build-fuzz/corpus-pieces tests/fuzz/pieces \
  -max_len=16384 -max_total_time="$piece_seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=64 \
  -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ 2>&1 | quiet
build-fuzz/tests/fuzz/kernel_cache_fuzzer build-fuzz/kernel-cache-corpus tests/fuzz/kernel_cache_seeds \
  -max_len=4096 -max_total_time="$cache_seconds" -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ 2>&1 | quiet

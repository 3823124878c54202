#!/usr/bin/env bash
# Figures for scenes of many spheres, printed (nothing is written to the repository): for scene
# files of 100k, 400k and 1M random spheres, how long loading takes and how much memory, how
# long the sphere BVH takes to build on 1 and 2 threads; the whole process's peak memory for a
# 1080p render of the 1M file on the GPU path (lavapipe) and on the CPU reference; and Embree's
# speed with single rays against packets. Builds first (ci/build.sh --bench: Embree included).
# About a minute on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh --bench >/dev/null
cmake --build build --parallel "$(nproc)" --target hexray_scale_bench hexray_embree_tracing_bench >/dev/null

lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
scenes=$(mktemp -d)
trap 'rm -rf "$scenes"' EXIT

echo "=== loading and BVH building"
for count in 100000 400000 1000000; do
  python3 tools/make-spheres-scene.py "$count" "$scenes/$count.json"
  ./build/tests/hexray_scale_bench "$scenes/$count.json" --rounds 3
done

# Peak resident memory of the whole process, from GNU time's "Maximum resident set size".
peak_mib() {
  local log=$scenes/time.log
  /usr/bin/time -v "$@" >"$scenes/out.log" 2>"$log"
  grep -h "wrote" "$scenes/out.log" "$log" || true
  awk -F': ' '/Maximum resident set size/ { printf "peak %.0f MiB\n", $2 / 1024 }' "$log"
}
echo "=== 1M spheres, whole process"
peak_mib ./build/hexray render "$scenes/1000000.json" --width 1920 --height 1080 --backend gpu -o "$scenes/gpu.png"
peak_mib ./build/hexray render "$scenes/1000000.json" --width 1920 --height 1080 --backend cpu --threads 2 \
  -o "$scenes/cpu.png"

echo "=== Embree: single rays against packets"
./build/tests/hexray_embree_tracing_bench --demo scenes/lecture-demo.json --spheres 1,100,10000,100000,1000000 \
  --rounds 5 --threads 2

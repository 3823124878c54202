#!/usr/bin/env bash
# Peak memory (GNU time's "Maximum resident set size") and wall time of the runs whose memory must
# not grow with what is rendered: a batch of 3000 small scenes of distinct structures (a generated
# kernel each) and one of 300 animation frames (one structure, the values moving), each in one
# `hexray render` with empty caches; many lights (100k, with no spheres and with 100) on the GPU
# path and the CPU reference; and loading scene files of 237 MiB (2.5 million spheres, 4.3 million
# lights). One run each, printed as markdown; about 25 minutes on two cores. Usage:
# tools/memory-bench.sh [SCENES] (default 3000; the frames are a tenth of it); needs build/hexray and
# build/tests/hexray_scale_bench.
set -euo pipefail
cd "$(dirname "$0")/.."

scenes=${1:-3000}
hexray=$PWD/build/hexray
lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Distinct structures: scene i's nodes are i's base-6 digits (sphere or plane, and its shader).
python3 - "$work" "$scenes" <<'PY'
import json, os, sys
work, count = sys.argv[1], int(sys.argv[2])
shaders = {"c": {"type": "constant", "color": [0.9, 0.5, 0.2]}, "l": {"type": "lambert", "color": [0.2, 0.7, 0.3]},
           "k": {"type": "checker", "color1": [0.9, 0.9, 0.9], "color2": [0.1, 0.1, 0.2], "size": 2}}
def scene(kinds, lights, shift):
    nodes = [{"geometry": {"type": "plane", "y": -1 - j}, "shader": s} if g == "p" else
             {"geometry": {"type": "sphere", "center": [-4 + 1.3 * j + shift, 0.5 * (j % 3), 8 + j], "radius": 0.6},
              "shader": s} for j, (g, s) in enumerate(kinds)]
    return {"image": {"width": 64, "height": 48}, "camera": {"position": [0, 2, -4], "pitch": -10},
            "lights": [{"position": [3 * i - 4, 6, 2 + i], "intensity": 40} for i in range(lights)],
            "shaders": shaders, "nodes": nodes}
for folder in ("distinct", "frames"):
    os.makedirs(os.path.join(work, folder))
for i in range(count):
    kinds, n = [], i
    while True:
        kinds.append(("p" if n % 2 else "s", "clk"[(n // 2) % 3]))
        n //= 6
        if n == 0:
            break
    json.dump(scene(kinds, 1 + i % 3, 0.0), open(os.path.join(work, "distinct", f"s{i:05d}.json"), "w"))
for i in range(max(count // 10, 1)):
    frame = scene([("p", "k"), ("s", "l"), ("s", "c"), ("s", "l")], 2, 0.01 * i)
    json.dump(frame, open(os.path.join(work, "frames", f"f{i:05d}.json"), "w"))
PY
python3 tools/make-lights-scene.py 100000 0 "$work/lights.json" --width 160 --height 90
python3 tools/make-lights-scene.py 100000 100 "$work/lights-spheres.json" --width 160 --height 90
python3 tools/make-spheres-scene.py 2540000 "$work/spheres-237.json"
python3 tools/make-lights-scene.py 4300000 0 "$work/lights-237.json"

# Runs a command with fresh caches; prints "| what | peak MiB | wall s |".
measure() {
  local what=$1
  shift
  rm -rf "$work/cache" "$work/out" && mkdir -p "$work/cache" "$work/out"
  XDG_CACHE_HOME=$work/cache /usr/bin/time -v "$@" >"$work/run.log" 2>"$work/time.log" || {
    echo "| $what | failed: $(grep -m1 error "$work/time.log") | |"
    return
  }
  awk -F': ' -v what="$what" '/Maximum resident set size/ { peak = $2 / 1024 }
    /Elapsed \(wall clock\)/ {
      n = split($2, t, ":")
      wall = t[n] + (n > 1 ? 60 * t[n - 1] : 0) + (n > 2 ? 3600 * t[n - 2] : 0)
    }
    END { printf "| %s | %.0f | %.1f |\n", what, peak, wall }' "$work/time.log"
}

echo "| run | peak MiB | wall s |"
echo "|---|---:|---:|"
measure "$scenes small scenes, distinct structures, one process (gpu)" \
  "$hexray" render "$work/distinct" --backend gpu -o "$work/out/"
measure "$((scenes / 10)) animation frames, one process (gpu)" \
  "$hexray" render "$work/frames" --backend gpu -o "$work/out/"
for scene in lights lights-spheres; do
  for backend in gpu cpu; do
    measure "$scene.json (100k lights, 160x90), $backend" "$hexray" render "$work/$scene.json" --backend "$backend" \
      -o "$work/out/$scene.png"
  done
done
# The loader alone: the scale bench's own figure, the peak right after loading (before its BVH).
for scene in spheres-237 lights-237; do
  ./build/tests/hexray_scale_bench "$work/$scene.json" --rounds 1 --threads 1 >"$work/run.log"
  sed -nE 's/.*load ([0-9]+) ms, peak ([0-9]+) MiB after loading.*/\2 \1/p' "$work/run.log" |
    awk -v what="loading $scene.json ($(($(stat -c %s "$work/$scene.json") >> 20)) MiB)" \
      '{ printf "| %s | %s | %.1f |\n", what, $1, $2 / 1000 }'
done

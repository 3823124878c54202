#!/usr/bin/env bash
# Many small scenes: 20 scenes of 320x240 (the shipped scenes, five camera angles each) rendered
# by one `hexray render` of all 20, against 20 processes of one scene each, on lavapipe. Both
# ways run in interleaved rounds after a warm-up round (the kernel cache and Mesa's shader cache
# warm for both); prints a markdown table of the medians and their ratio. Run it on an
# idle machine. Usage: tools/batch-bench.sh [ROUNDS] (default 5); needs build/hexray.
set -euo pipefail
cd "$(dirname "$0")/.."

rounds=${1:-5}
hexray=$PWD/build/hexray
lavapipe_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
export VK_DRIVER_FILES="$lavapipe_icd" VK_ICD_FILENAMES="$lavapipe_icd"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scenes: each shipped scene at 320x240, its camera turned by 0, 5, ... 20 degrees of yaw.
python3 - "$work/scenes" scenes/*.json <<'EOF'
import json, os, sys
out = sys.argv[1]
os.makedirs(out)
for path in sys.argv[2:]:
    scene = json.load(open(path))
    if "nodes" not in scene:
        continue  # not a scene: scenes/hexray-expectations.json
    scene["image"].update(width=320, height=240)
    base = os.path.splitext(os.path.basename(path))[0]
    yaw = scene["camera"].get("yaw", 0)
    for turn in range(5):
        scene["camera"]["yaw"] = yaw + 5 * turn
        json.dump(scene, open(os.path.join(out, f"{base}-{turn}.json"), "w"))
EOF
scene_files=("$work"/scenes/*.json)
count=${#scene_files[@]}
mkdir "$work/out"

milliseconds() { date +%s%3N; }
one_process() { "$hexray" render "${scene_files[@]}" --backend gpu -o "$work/out" >/dev/null; }
one_process_each() {
  for scene in "${scene_files[@]}"; do
    "$hexray" render "$scene" --backend gpu -o "$work/out" >/dev/null
  done
}
timed() {  # prints how long the command took, in ms
  local start
  start=$(milliseconds)
  "$@"
  echo $(($(milliseconds) - start))
}
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

one_process
one_process_each
together=()
apart=()
for ((round = 0; round < rounds; ++round)); do
  together+=("$(timed one_process)")
  apart+=("$(timed one_process_each)")
done
together_ms=$(printf '%s\n' "${together[@]}" | median)
apart_ms=$(printf '%s\n' "${apart[@]}" | median)

echo "| $count scenes of 320x240 on lavapipe ($rounds rounds) | median, whole run | per scene |"
echo "|---|---:|---:|"
awk -v n="$count" -v together="$together_ms" -v apart="$apart_ms" 'BEGIN {
  printf "| %d processes, one scene each | %.0f ms | %.1f ms |\n", n, apart, apart / n
  printf "| one process, `hexray render` of all %d | %.0f ms | %.1f ms |\n", n, together, together / n
  printf "| speed-up of one process | %.1fx | |\n", apart / together
}'

#!/usr/bin/env bash
# Regenerates docs/performance.md, docs/performance.csv and docs/performance.png: the speed
# against error benchmark (hexray bench), the scaling curve over random-sphere scenes, and
# whole-process times. Installs and builds first (ci/build.sh --bench: the usual packages plus
# Embree 3 and matplotlib, which only this report uses; without Embree the bench drops its rows).
set -euo pipefail
cd "$(dirname "$0")/.."

bash ci/build.sh --bench >/dev/null
start_seconds=$(date +%s)

# The sphere curve: N random spheres over a plane at 1080p, one sample per pixel, three rounds
# (a 100k-sphere frame of the CPU reference alone takes several seconds here).
curve_counts=1,10,100,1000,10000,100000
curve_rounds=3

hexray=./build/hexray
bench_demo=$($hexray bench scenes/lecture-demo.json --width 1920 --height 1080 --csv docs/performance-demo.csv 2>/dev/null)
bench_spheres=$($hexray bench scenes/spheres-and-lights.json --csv docs/performance-spheres.csv 2>/dev/null)
bench_curve=$($hexray bench --spheres $curve_counts --width 1920 --height 1080 --samples 1 --rounds $curve_rounds --max-frame-seconds 30 \
  --csv docs/performance-curve.csv 2>/dev/null)
{ cat docs/performance-demo.csv; tail -n +2 docs/performance-spheres.csv; tail -n +2 docs/performance-curve.csv; } \
  > docs/performance.csv
rm docs/performance-demo.csv docs/performance-spheres.csv docs/performance-curve.csv
/usr/bin/python3 ci/plot-pareto.py docs/performance.csv docs/performance.png

# Whole process: `hexray render` of the demo at 1080p to PNG, warm (Mesa's shader cache filled)
# and cold (cache disabled); seven runs each, interleaved; milliseconds.
output=$(mktemp -d)
whole_process() {
  local start end
  start=$(date +%s%N)
  "$@" $hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o "$output/demo.png" >/dev/null
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}
$hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o "$output/demo.png" >/dev/null  # fill the cache
warm=() cold=()
for _ in 1 2 3 4 5 6 7; do
  warm+=("$(whole_process env)")
  cold+=("$(whole_process env MESA_SHADER_CACHE_DISABLE=true)")
done
rm -rf "$output"
median() { printf '%s\n' "$@" | sort -n | sed -n 4p; }
elapsed=$(( $(date +%s) - start_seconds ))

device=$($hexray devices | sed -n 's/^\* [0-9]*: //p')
embree_line=$(printf '%s\n' "$bench_curve" | sed -n 's/^Embree: \(.*\)\.$/\1 (Debian libembree-dev)./p')
[ -n "$embree_line" ] || embree_line="Embree: not built in, so no Embree rows."
{
  cat <<HEADER
# Performance: speed against error

Regenerate with \`bash ci/bench-report.sh\` (it installs and builds first). It runs
\`hexray bench\` (five interleaved rounds of every configuration in one process) on the demo
scene at 1920×1080 and on spheres-and-lights at 960×540, then the scaling curve (random
spheres over a plane, N = ${curve_counts//,/, }, at 1920×1080, ${curve_rounds} rounds), writes
[performance.csv](performance.csv) and the plot below, and times whole processes.
Device: ${device}. ${embree_line} Generated $(date -u +%Y-%m-%d); the three benches and the
whole-process runs took ${elapsed} s. The machine is shared and noisy: compare figures from
the same run only.

Backends: **lavapipe** = the compute shader on Mesa's CPU Vulkan driver, timing the pipeline
\`hexray render\` uses (the 8-bit image encoded on the device; the pixel classes for the
topology column come from one untimed run of the comparison pipeline); **cpu-reference** =
the double-precision reference (\`host/cpu\`), which also computes every decision's margin
and is built for clarity, not speed; **embree** = Intel's Embree 3 on the same scenes, camera
rays and shading (\`host/embree\`: spheres as Embree sphere points in float, camera-relative;
planes analytic; one ray at a time with \`rtcIntersect1\` / \`rtcOccluded1\`; hit points
rebuilt and shaded in double), as a yardstick for what a tuned CPU tracer does here;
**lavapipe hand-written** (demo scene only) = \`shaders/lecture_demo_ceiling.comp\`, a
straight-line kernel with that scene's values as literals and textbook float arithmetic, as
the yardstick for the data-driven shader: lavapipe's ceiling for this scene on this machine
(it writes no pixel classes, so its topology column is empty).

Columns: **Mpix/s** = pixels / render time (lavapipe: dispatch time from timestamps, after a
warm-up dispatch; CPU reference: wall time, all cores, BVH build included; Embree: tracing and
shading wall time, all cores, its BVH build excluded), median and best of the rounds;
**frame ms** = median wall time of the whole frame in-process (upload, render, read back;
Embree: with its BVH build); **RMSE**, **max abs** and **> 1 level** = 8-bit error against
the CPU reference at 64 samples per pixel (the converged image); **topology mismatches** =
pixels whose node, checker cell or lit lights differ from the CPU reference at the same
sample count, outside its ambiguous pixels.

![Speed against error; speed and cost per pixel against the number of spheres](performance.png)

## Demo scene, 1920×1080

$bench_demo

## spheres-and-lights, 960×540

$bench_spheres

## Scaling: N random spheres over a plane, 1920×1080

\`hexray bench --spheres ${curve_counts} --width 1920 --height 1080 --samples 1 --rounds ${curve_rounds} --max-frame-seconds 30\`:
\`makeRandomSpheresScene(N, 1)\`, spheres of radius 0.5–2.5 on a checkered floor whose side
grows as √N (the density stays the same), two lights, camera looking down over it. Before
the rounds, each backend renders every N once at a fraction of the resolution; a backend
whose full frame that predicts to exceed \`--max-frame-seconds\` (30) is not measured at that
N (the notes under the table say which). **core-ns per pixel** = render time × threads /
pixels: with log N traversal it grows by a constant step per decade of N. **vs Embree** =
this row's Mpix/s over Embree's at the same N (above 1: faster than Embree). The error
columns here are against the CPU reference at the **same** sample count (1 spp), not a
converged one (which at 100k spheres would take longer than the whole report), so the
cpu-reference rows read 0 by construction.

$bench_curve

## Whole process

\`hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o demo.png\`, from exec
to exit, seven interleaved runs (median; all runs in ms):

| Mesa shader cache | median ms | runs |
|---|---:|---|
| warm | $(median "${warm[@]}") | ${warm[*]} |
| cold (\`MESA_SHADER_CACHE_DISABLE=true\`) | $(median "${cold[@]}") | ${cold[*]} |
HEADER
} > docs/performance.md
echo "wrote docs/performance.md, docs/performance.csv, docs/performance.png"

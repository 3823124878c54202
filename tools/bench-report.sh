#!/usr/bin/env bash
# Regenerates docs/performance.md, docs/performance.csv and docs/performance.png: the speed
# against error benchmark (hexray bench), the scaling curve over random-sphere scenes, and
# whole-process times (with a million-sphere frame against Embree's, tools/frame-bench.py).
# Installs and builds first (ci/build.sh --bench: the usual packages plus Embree 3 and
# matplotlib, which only this report uses; without Embree the bench drops its rows).
set -euo pipefail
cd "$(dirname "$0")/.."

# The hand-written text above the marker line in docs/performance.md is kept; the rest is written afresh.
marker='<!-- Everything below is written by tools/bench-report.sh: edit the script, not the text. -->'
grep -qxF "$marker" docs/performance.md || { echo "docs/performance.md has no marker line: $marker" >&2; exit 1; }
handwritten=$(awk -v marker="$marker" '$0 == marker {exit} {print}' docs/performance.md)

bash ci/build.sh --bench >/dev/null
start_seconds=$(date +%s)

# The sphere curve: N random spheres over a plane at 1080p, one sample per pixel, three rounds
# (a million-sphere frame of the CPU reference alone takes several seconds here).
curve_counts=1,10,100,1000,10000,100000,1000000
curve_rounds=3

hexray=./build/hexray
bench_demo=$($hexray bench scenes/lecture-demo.json --width 1920 --height 1080 --csv docs/performance-demo.csv 2>/dev/null)
bench_spheres=$($hexray bench scenes/spheres-and-lights.json --width 960 --height 540 \
  --csv docs/performance-spheres.csv 2>/dev/null)
bench_curve=$($hexray bench --spheres $curve_counts --width 1920 --height 1080 --samples 1 --rounds $curve_rounds --max-frame-seconds 30 \
  --csv docs/performance-curve.csv 2>/dev/null)
{ cat docs/performance-demo.csv; tail -n +2 docs/performance-spheres.csv; tail -n +2 docs/performance-curve.csv; } \
  > docs/performance.csv
rm docs/performance-demo.csv docs/performance-spheres.csv docs/performance-curve.csv
/usr/bin/python3 tools/plot-pareto.py docs/performance.csv docs/performance.png
targets=$(/usr/bin/python3 tools/performance-targets.py docs/performance.csv)

# Whole process: `hexray render` of the demo at 1080p to PNG, warm (hexray's kernel cache and
# Mesa's shader cache filled), cold (Mesa's cache disabled) and new (a scene never seen: both
# caches empty or disabled); seven runs each, interleaved; milliseconds.
output=$(mktemp -d)
whole_process() {
  local start end
  start=$(date +%s%N)
  "$@" $hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o "$output/demo.png" >/dev/null
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}
export XDG_CACHE_HOME="$output/cache"
$hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o "$output/demo.png" >/dev/null  # fill the caches
warm=() cold=() new=()
for _ in 1 2 3 4 5 6 7; do
  warm+=("$(whole_process env)")
  cold+=("$(whole_process env MESA_SHADER_CACHE_DISABLE=true)")
  new+=("$(whole_process env MESA_SHADER_CACHE_DISABLE=true XDG_CACHE_HOME="$output/empty-$RANDOM")")
done
unset XDG_CACHE_HOME
rm -rf "$output"
median() { printf '%s\n' "$@" | sort -n | sed -n 4p; }

# A whole frame of a million spheres against Embree's (tools/frame-bench.py prints its own table).
frame=$(/usr/bin/python3 tools/frame-bench.py --spheres 1000000 --rounds 3)

# Many scenes in one process against one process each (tools/batch-bench.sh prints its own table).
batch=""
if [ -f tools/batch-bench.sh ]; then
  batch=$(bash tools/batch-bench.sh)
fi
elapsed=$(( $(date +%s) - start_seconds ))

device=$($hexray devices | sed -n 's/^\* [0-9]*: //p')
embree_line=$(printf '%s\n' "$bench_curve" | sed -n 's/^Embree: \(.*\)\.$/\1 (Debian libembree-dev)./p')
[ -n "$embree_line" ] || embree_line="Embree: not built in, so no Embree rows."
{
  printf '%s\n\n%s\n\n' "$handwritten" "$marker"
  cat <<HEADER
## Results: speed against error

Regenerate with \`bash tools/bench-report.sh\` (it installs and builds first). It runs
\`hexray bench\` (five interleaved rounds of every configuration in one process) on the demo
scene at 1920×1080 and on spheres-and-lights at 960×540, then the scaling curve (random
spheres over a plane, N = ${curve_counts//,/, }, at 1920×1080, ${curve_rounds} rounds), writes
[performance.csv](performance.csv) and the plot below, and times whole processes and batches.
Device: ${device}. ${embree_line} Generated $(date -u +%Y-%m-%d); the three benches and the
whole-process runs took ${elapsed} s. The machine is shared and noisy: compare figures from
the same run only.

Backends: **lavapipe** = the compute shader on Mesa's CPU Vulkan driver, as \`hexray render\`
runs it (the 8-bit image encoded on the device; the pixel classes for the topology column come
from one untimed run that writes them), for each precision with **culling** off (the kernel
generated for the whole scene) and on (a kernel per class of screen tiles, each with only the
tests its rays can need; the same image, see
[culling](#what-makes-the-gpu-path-fast) above); "(auto)" marks the precision \`auto\`
picks; **lavapipe hand-written** (demo scene only) = \`host/bench/lecture_demo_ceiling.comp\`, the
demo scene as straight-line code with its values as literals and textbook float arithmetic, run
through the renderer's public interface: the yardstick for what lavapipe can do for that scene;
**cpu-reference** = the double-precision reference (\`host/cpu\`), which also computes every
decision's margin and is built for clarity, not speed; **embree N-ray packets (f32 shading)** =
Intel's Embree 3 as its authors would use it, on the same scenes, camera rays and shading model
(\`host/embree/embree_packet_renderer.*\`): the widest packet the CPU runs natively (16 rays on
AVX-512, 8 on AVX2, else 4), each the camera rays of a square tile (4×4, 4×2, 2×2) in one coherent
\`rtcIntersectN\`, the shadow rays toward each light in one incoherent \`rtcOccludedN\`, spheres as
Embree sphere points and planes analytic, everything in float and camera-relative, shaded over the
packet's lanes in structure-of-arrays loops, denormals flushed to zero; **embree 8-ray packets
(f64 shading)** and **embree single rays (f64 shading)** (on request, \`--backends
embree-f64-packets,embree-f64-single\`) = Embree's hits rebuilt and shaded in double through the
CPU reference's code (\`host/embree/embree_renderer.*\`): what hexray's double shading costs on
Embree's traversal, not Embree's own speed. \`--backends\` chooses the rows
([command-line.md](command-line.md)); the **kernel**, **precision** and **culling** columns tell
apart rows that differ in those.

Columns: **Mpix/s** = pixels / render time (lavapipe: dispatch time from timestamps, after a
warm-up dispatch of each kernel; CPU reference: wall time, all cores, BVH build included;
Embree: tracing and shading wall time, all cores, its BVH build excluded), median and best of
the rounds; **frame ms** = median wall time of the whole frame in-process (planning, upload,
render, read back); **vs hand-written** / **vs Embree** = this row's Mpix/s over the
hand-written kernel's / the fastest Embree row's at the same scene and sample count;
**primary tests/px**, **shadow rays/px**, **shadow tests/px** = what the row's generated kernel
runs per pixel on average (lavapipe runs every test a straight-line kernel contains, whatever
the pixel): camera-ray node tests, lights with a shadow test, and shadow node tests;
**sampling error** = 8-bit RMSE against the CPU reference at 64 samples per pixel (the
converged image): at 1 spp almost all of it is aliasing, the same for every backend;
**precision error** = 8-bit RMSE (and the share of pixels more than one level off) against the
CPU reference at the **same** sample count, on the pixels whose decisions it calls clear of
rounding: what the backend's arithmetic costs; **mean FLIP** = mean LDR-FLIP (the perceptual
difference \`compare\` and \`diff\` report, docs/diff.md) against that same reference, every pixel
(in [0, 1]; 0 = indistinguishable); **topology mismatches** = pixels whose node,
checker cell or lit lights differ from that reference, outside its ambiguous pixels.

## Targets

Each performance target of the current issues against this run's figures
(\`tools/performance-targets.py docs/performance.csv\`):

$targets

![Speed against error; speed and cost per pixel against the number of spheres](performance.png)

## Demo scene, 1920×1080

\`hexray bench scenes/lecture-demo.json --width 1920 --height 1080\`

$bench_demo

## spheres-and-lights, 960×540

\`hexray bench scenes/spheres-and-lights.json --width 960 --height 540\`

$bench_spheres

## Scaling: N random spheres over a plane, 1920×1080

\`hexray bench --spheres ${curve_counts} --width 1920 --height 1080 --samples 1 --rounds ${curve_rounds} --max-frame-seconds 30\`:
\`makeRandomSpheresScene(N, 1)\`, spheres of radius 0.5–2.5 on a checkered floor whose side
grows as √N (the density stays the same), two lights, camera looking down over it. Before
the rounds, each backend renders every N once at a fraction of the resolution; a backend
whose full frame that predicts to exceed \`--max-frame-seconds\` (30) is not measured at that
N (the notes under the table say which). **host plan ms** = the GPU's planning (the structures
it builds on the host for the scene: its candidate lists), **upload ms** = packing and uploading
them: both are in frame ms, not in the render time. **core-ns per pixel** = render time ×
threads / pixels. **vs Embree** = this row's Mpix/s over the fastest Embree row's at the same N
(above 1: faster than Embree). The error columns here are against the CPU reference at the same
sample count (1 spp), so the cpu-reference rows read 0 by construction.

$bench_curve

## Whole process

\`hexray render scenes/lecture-demo.json --backend gpu --width 1920 --height 1080 -o demo.png\`, from exec
to exit, seven interleaved runs (median; all runs in ms):

| caches | median ms | runs |
|---|---:|---|
| warm (hexray's kernel cache and Mesa's shader cache filled) | $(median "${warm[@]}") | ${warm[*]} |
| cold driver (\`MESA_SHADER_CACHE_DISABLE=true\`; the kernel's SPIR-V cached) | $(median "${cold[@]}") | ${cold[*]} |
| a scene never seen (an empty kernel cache, Mesa's disabled: glslang and the driver compile) | $(median "${new[@]}") | ${new[*]} |

## A whole frame against Embree's

\`tools/frame-bench.py --spheres 1000000 --rounds 3\`: \`hexray render\` of a file of a million random
spheres (\`tools/make-spheres-scene.py\`) at 1920×1080 to PNG, from exec to exit, against
\`tests/bench/embree_frame.cpp\`, which loads the same file with the same loader, builds Embree's
scene, traces it with the bench's Embree row and writes the PNG; interleaved.

$frame

## Many scenes in one process

$batch
HEADER
} > docs/performance.md
echo "wrote docs/performance.md, docs/performance.csv, docs/performance.png"

#!/usr/bin/env bash
# Regenerates docs/performance.md, docs/performance.csv and docs/performance.png: the speed
# against error benchmark (hexray bench) and whole-process times. Needs a build
# (bash ci/build.sh); installs Debian's python3-matplotlib for the plot.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends python3-matplotlib
fi

hexray=./build/hexray
bench_demo=$($hexray bench scenes/lecture-demo.json --width 1920 --height 1080 --csv docs/performance-demo.csv 2>/dev/null)
bench_spheres=$($hexray bench scenes/spheres-and-lights.json --csv docs/performance-spheres.csv 2>/dev/null)
{ cat docs/performance-demo.csv; tail -n +2 docs/performance-spheres.csv; } > docs/performance.csv
rm docs/performance-demo.csv docs/performance-spheres.csv
/usr/bin/python3 ci/plot-pareto.py docs/performance.csv docs/performance.png

# Whole process: `hexray render` of the demo at 1080p to PNG, warm (Mesa's shader cache filled)
# and cold (cache disabled); seven runs each, interleaved; milliseconds.
output=$(mktemp -d)
whole_process() {
  local start end
  start=$(date +%s%N)
  "$@" $hexray render scenes/lecture-demo.json --width 1920 --height 1080 -o "$output/demo.png" >/dev/null
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}
$hexray render scenes/lecture-demo.json --width 1920 --height 1080 -o "$output/demo.png" >/dev/null  # fill the cache
warm=() cold=()
for _ in 1 2 3 4 5 6 7; do
  warm+=("$(whole_process env)")
  cold+=("$(whole_process env MESA_SHADER_CACHE_DISABLE=true)")
done
rm -rf "$output"
median() { printf '%s\n' "$@" | sort -n | sed -n 4p; }

device=$($hexray devices | sed -n 's/^\* [0-9]*: //p')
{
  cat <<HEADER
# Performance: speed against error

Regenerate with \`bash ci/bench-report.sh\` (after \`bash ci/build.sh\`). It runs
\`hexray bench\` (five interleaved rounds of every configuration in one process) on the demo
scene at 1920×1080 and on spheres-and-lights at 960×540, writes
[performance.csv](performance.csv) and the plot below, and times whole processes.
Device: ${device}. Generated $(date -u +%Y-%m-%d). The machine is shared and noisy: compare
figures from the same run only.

The GPU rows time the pipeline \`compare\` uses (linear output plus the per-pixel
classification, so that the error columns can be computed); \`render\` specializes a
pipeline that writes only the 8-bit image, which is slightly faster.

Columns: **Mpix/s** = pixels / render time (GPU: dispatch time from timestamps, after a
warm-up dispatch; CPU reference: wall time, all cores), median and best of the rounds;
**frame ms** = median wall time of the whole frame in-process (upload, render, read back);
**RMSE**, **max abs** and **> 1 level** = 8-bit error against the CPU reference at 64 samples
per pixel (the converged image); **topology mismatches** = pixels whose node, checker cell
or lit lights differ from the CPU reference at the same sample count, outside its ambiguous
pixels.

![Speed against error](performance.png)

## Demo scene, 1920×1080

$bench_demo

## spheres-and-lights, 960×540

$bench_spheres

## Whole process

\`hexray render scenes/lecture-demo.json --width 1920 --height 1080 -o demo.png\`, from exec
to exit, seven interleaved runs (median; all runs in ms):

| Mesa shader cache | median ms | runs |
|---|---:|---|
| warm | $(median "${warm[@]}") | ${warm[*]} |
| cold (\`MESA_SHADER_CACHE_DISABLE=true\`) | $(median "${cold[@]}") | ${cold[*]} |
HEADER
} > docs/performance.md
echo "wrote docs/performance.md, docs/performance.csv, docs/performance.png"

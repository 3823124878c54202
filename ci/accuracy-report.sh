#!/usr/bin/env bash
# Regenerates docs/accuracy.md: every shipped scene (hard cases included) in every precision,
# GPU against the CPU reference. Needs a build (bash ci/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

table=$(./build/hexray compare --all scenes/ || true)  # f32-naive rows are meant to fail
device=$(./build/hexray devices | sed -n 's/^\* [0-9]*: //p')
{
  cat <<HEADER
# Accuracy: GPU against the CPU reference, per scene and precision

Regenerate with \`bash ci/accuracy-report.sh\` (runs \`build/hexray compare --all scenes/\`).
Device: ${device}. Generated $(date -u +%Y-%m-%d).

Columns: **topology mismatches** = pixels the CPU reference calls unambiguous whose visible
node, checker cell or set of lit lights differs on the GPU (must be 0 for f32 and f64);
**ambiguous** = share of pixels where some decision lies within float32 rounding of flipping
(the CPU reference's margin test, see README); **max abs** and **RMSE** = 8-bit colour error
on the unambiguous pixels, in levels; **> 1 level** = share of unambiguous pixels more than
one level off; **GPU ms** = dispatch time (timestamps, after a warm-up); **auto** = the
precision \`--precision auto\` picks. f32-naive rows are the textbook formulation, kept to
show what the robust one buys; they are reported, not judged.

HEADER
  echo "$table"
  cat <<HARD

## Hard cases against analytic ground truth

Each scene in \`scenes/hard/\` is also checked, pixel by pixel, against closed-form answers
computed in long double by the test (\`tests/gpu/hard_case_test.cpp\`): silhouettes, horizon
dip, which node is nearer, checker parity, lit or shadowed, known uniform values, shadow
radius. Violations per scene and precision (0 is required for f32 and f64):

| scene | f32-naive | f32 | f64 |
|---|---:|---:|---:|
HARD
  ./build/tests/hexray_gpu_tests --gtest_filter='*HardCase*' 2>/dev/null |
    sed -n 's/^hard \([a-z0-9-]*\) \(f32-naive\|f32\|f64\): \([0-9]*\) violations.*/\1 \2 \3/p' |
    awk '{v[$1" "$2]=$3; s[$1]=1} END {for (k in s) printf "| %s | %s | %s | %s |\n", k, v[k" f32-naive"], v[k" f32"], v[k" f64"]}' |
    sort
  cat <<ORACLE

## Exact oracle: both renderers on generated hard rays

Each of 605 generated hard rays (\`tests/oracle/hard_rays.cpp\`) is a one-pixel scene, traced by the
shader (f32, f64; **gpu auto** = the one \`auto\` picks for that ray's scene) and explained by the CPU
reference, and judged against the exact oracle (MPFR, \`tests/oracle/\`) on the direction that
renderer followed, at its own precision (README, "Exact oracle"). **decisions** = well-conditioned
decisions right / judged (which node, checker parity, each light's status; at least 64 units of
roundoff from flipping); **distances** = distances judged (one unit of roundoff moves them by at
most 2 ulps of the hit's scale S); **max ulps** = the largest distance error in ulps of S (the
bound is 8); **values** / **max units** = normals, cos θ and r² judged, and the largest error in
their own units (the bound is 8). Regenerate this table alone with
\`build/tests/hexray_gpu_tests --gtest_filter='OracleSuiteTest.*' | sed -n 's/^oracle-row: //p'\`.

| family | renderer | rays | decisions | distances | max ulps | values | max units |
|---|---|---:|---:|---:|---:|---:|---:|
ORACLE
  ./build/tests/hexray_gpu_tests --gtest_filter='OracleSuiteTest.*' 2>/dev/null | sed -n 's/^oracle-row: //p'
  cat <<COST

## Cost of float64

\`hexray render scenes/lecture-demo.json --width 1920 --height 1080\`, dispatch time, five
interleaved runs of each precision in this run (median, then all runs):

| precision | median ms | runs |
|---|---:|---|
COST
  for run in 1 2 3 4 5; do
    for precision in f32 f64; do
      ./build/hexray render scenes/lecture-demo.json --backend gpu -o /tmp/hexray-accuracy-cost.png \
        --width 1920 --height 1080 --precision "$precision" |
        sed -n "s/.*gpu $precision .*render \([0-9.]*\) ms.*/$precision \1/p"
    done
  done | awk '{t[$1]=t[$1]" "$2} END {for (p in t) print p, t[p]}' | sort |
    while read -r precision times; do
      median=$(printf '%s\n' $times | sort -n | sed -n 3p)
      echo "| $precision | $median | $times |"
    done
  rm -f /tmp/hexray-accuracy-cost.png
} > docs/accuracy.md
echo "wrote docs/accuracy.md"

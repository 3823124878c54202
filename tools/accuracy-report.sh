#!/usr/bin/env bash
# Regenerates docs/accuracy.md: every shipped scene (hard cases included) in every precision,
# GPU against the CPU reference. Needs a build (bash ci/build.sh). The hand-written text above
# the marker line in docs/accuracy.md is kept; everything below it is written afresh.
set -euo pipefail
cd "$(dirname "$0")/.."

marker='<!-- Everything below is written by tools/accuracy-report.sh: edit the script, not the text. -->'
grep -qxF "$marker" docs/accuracy.md || { echo "docs/accuracy.md has no marker line: $marker" >&2; exit 1; }
handwritten=$(awk -v marker="$marker" '$0 == marker {exit} {print}' docs/accuracy.md)

table=$(./build/hexray compare --all scenes/ || true)  # f32-naive rows are meant to fail
device=$(./build/hexray devices | sed -n 's/^\* [0-9]*: //p')
{
  printf '%s\n\n%s\n\n' "$handwritten" "$marker"
  cat <<HEADER
## Results: GPU against the CPU reference, per scene and precision

Regenerate with \`bash tools/accuracy-report.sh\` (runs \`build/hexray compare --all scenes/\`).
Device: ${device}. Generated $(date -u +%Y-%m-%d).

Columns: **topology mismatches** = pixels whose visible node, checker cell or set of lit lights
differs on the GPU in a decision the CPU reference did not find near-tied (must be 0 for f32
and f64); **ambiguous** = share of pixels with some decision within its error bound of
flipping, at the row's precision (the CPU reference's margins, see
[compare.md](compare.md#how-the-gpu-and-cpu-renderers-are-compared)); **excused** = share
of pixels left partly unchecked (a near-tied decision went the other way, or the colour was not
comparable); **max abs** and **RMSE** = 8-bit colour error on the pixels whose colours are
compared, in levels; **> 1 level** = share of those more than one level off; **GPU ms** =
dispatch time (timestamps, after a warm-up); **auto** = the precision \`--precision auto\`
picks. f32-naive rows are the textbook formulation, kept to show what the robust one buys; they
are reported, not judged. "FAIL (too ambiguous)": more than 5 % of the pixels are near-tied,
so \`compare\` will not call the rows verified; the hard scenes that fail so are built on knife
edges (rows exactly on checker edges, a light in the floor or on a sphere, rays grazing a plane,
a sphere float32 cannot resolve) and are checked against analytic truth below instead.

HEADER
  echo "$table"
  cat <<SHARES

## Ambiguous share, before and after per-decision bounds (issue 12)

Before: one margin per pixel, the smallest of its decisions, against one bound of 128 float32
units (2⁻¹⁷) at every precision; an ambiguous pixel was left out whole. After: a bound per
decision (twice the camera direction's roundoff plus 16 units, at the compared precision: see
[compare.md](compare.md)), a plane's checker cell measured per axis, the margin of a sphere holding the camera
against its own points, and a near-tie excusing only its own part of the pixel. Before, measured
at main 2c1cb24 with \`hexray compare scenes/lecture-demo.json\` and \`hexray compare\` of
\`makeRandomSpheresScene(3000, 1)\` written as a scene file (320 x 180; \`--spp 4\`):

| scene | before: ambiguous | after: ambiguous (f32, f64) |
|---|---:|---:|
SHARES
  ./build/tests/hexray_unit_tests --gtest_filter='RandomSpheresMargins.*:*ShippedSceneMargins*lecture_demo' |
    awk '/\[ ambiguous \] lecture-demo.json/ {demo=$5}
         /\[ ambiguous \] 3000 random spheres, 1 spp, f32/ {r1f32=$10} /1 spp, f64/ {r1f64=$10}
         /\[ ambiguous \] 3000 random spheres, 4 spp, f32/ {r4f32=$10} /4 spp, f64/ {r4f64=$10}
         END {
           printf "| lecture-demo (f32 by auto) | 2.149 %% | %s %% (f64: see the table above) |\n", demo
           printf "| 3000 random spheres, 1 spp | 1.358 %% | %s %%, %s %% |\n", r1f32, r1f64
           printf "| 3000 random spheres, 4 spp | 4.309 %% | %s %%, %s %% |\n", r4f32, r4f64
         }'
  cat <<SHARES2

The excused share (what the comparison really leaves unchecked) is in the table above: on the
demo scene in f32 0.62 % (the rows on checker edges near the horizon, where the GPU takes the
other side), against 2.15 % of pixels left out whole before. Issue 12 quotes 7.8 % for a
3000-sphere scene; the scene of \`makeRandomSpheresScene(3000, 1)\` measured 1.36 % (4.31 % at
4 samples per pixel) on the same code, so that figure came from another configuration.
SHARES2
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
renderer followed, at its own precision ([Exact oracle](#exact-oracle)). **decisions** = well-conditioned
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

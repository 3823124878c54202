#!/usr/bin/env bash
# Regenerates docs/accuracy.md: every shipped scene (hard cases included) in every precision,
# GPU against the CPU reference. Needs a build (bash ci/build.sh). The hand-written text above
# the marker line in docs/accuracy.md is kept; everything below it is written afresh.
set -euo pipefail
cd "$(dirname "$0")/.."

marker='<!-- Everything below is written by tools/accuracy-report.sh: edit the script, not the text. -->'
grep -qxF "$marker" docs/accuracy.md || { echo "docs/accuracy.md has no marker line: $marker" >&2; exit 1; }
handwritten=$(awk -v marker="$marker" '$0 == marker {exit} {print}' docs/accuracy.md)

# Everything is read as data: compare's and render's --json documents, and the properties the
# accuracy tests record (--gtest_output=json), turned into tables by tools/accuracy-tables.py.
data=$(mktemp -d)
trap 'rm -rf "$data" docs/accuracy.md.tmp' EXIT
tables() { /usr/bin/python3 tools/accuracy-tables.py "$@"; }
gtest() {  # binary filter output.json: the tests must pass, or their figures are not reported
  if ! "$1" --gtest_filter="$2" --gtest_output="json:$3" >/dev/null 2>&1; then
    echo "$1 --gtest_filter='$2' failed" >&2
    exit 1
  fi
}
status=0
./build/hexray compare --all scenes/ --json "$data/compare.json" >/dev/null 2>&1 || status=$?
if [ "$status" -gt 1 ]; then  # 1 is a comparison that failed: reported in the table
  echo "hexray compare --all scenes/ exited $status" >&2
  exit 1
fi
device=$(tables device "$data/compare.json")
gtest ./build/tests/hexray_unit_tests 'RandomSpheresMargins.*:*ShippedSceneMargins*lecture_demo' "$data/margins.json"
gtest ./build/tests/hexray_gpu_tests '*HardCase*' "$data/hard.json"
gtest ./build/tests/hexray_gpu_tests 'OracleSuiteTest.EveryWellConditioned*' "$data/oracle.json"
for run in 1 2 3 4 5; do
  for precision in f32 f64; do
    ./build/hexray render scenes/lecture-demo.json --backend gpu -o "$data/cost.png" --width 1920 --height 1080 \
      --precision "$precision" --json "$data/cost-$precision-$run.json" >/dev/null 2>&1
  done
done
{
  printf '%s\n\n%s\n\n' "$handwritten" "$marker"
  cat <<HEADER
## Results: GPU against the CPU reference, per scene and precision

Regenerate with \`bash tools/accuracy-report.sh\` (runs \`build/hexray compare --all scenes/ --json\` and the
accuracy tests with \`--gtest_output=json\`, and reads their figures from the documents).
Device: ${device}. Generated $(date -u +%Y-%m-%d).

Columns: **topology mismatches** = pixels whose visible node, checker cell or set of lit lights
differs on the GPU in a decision the CPU reference did not find near-tied (must be 0 for f32
and f64); **ambiguous** = share of pixels with some decision within its error bound of
flipping, at the row's precision (the CPU reference's margins, see
[compare.md](compare.md#how-the-gpu-and-cpu-renderers-are-compared)); **excused** = share
of pixels left partly unchecked (a near-tied decision went the other way, or the colour was not
comparable); **max abs** and **RMSE** = 8-bit colour error on the pixels whose colours are
compared, in levels; **mean FLIP** = mean LDR-FLIP of the 8-bit outputs, every pixel, at 67
pixels per degree (the perceptual difference, in [0, 1]: docs/diff.md); **> 1 level** = share of
those more than one level off; **GPU ms** = dispatch time (timestamps, after a warm-up);
**auto** = the precision \`--precision auto\` picks. f32-naive rows are the textbook formulation,
kept to show what the robust one buys; they are reported, not judged. "expected (too
ambiguous)": more than 5 % of the pixels are near-tied, so \`compare\` will not call the rows
verified, and \`scenes/hexray-expectations.json\` says so in advance (docs/compare-expectations.md):
the hard scenes built on knife edges (rows exactly on checker edges, a light in the floor or on a
sphere, rays grazing a plane, a sphere float32 cannot resolve) are checked against analytic truth
below instead. Such a row counts as expected, not failed, so \`compare\` on the whole tree passes
(the count line under the table); a row so marked that stopped being ambiguous would fail it.

HEADER
  tables compare "$data/compare.json"
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
  tables shares "$data/margins.json"
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
  tables hard "$data/hard.json"
  cat <<ORACLE

## Exact oracle: both renderers on generated hard rays

Each of 605 generated hard rays (\`tests/oracle/hard_rays.cpp\`) is a one-pixel scene, traced by the
shader (f32, f64; **gpu auto** = the one \`auto\` picks for that ray's scene; **data-driven** = the
kernel of scenes past a generated kernel's capacity, with candidate lists) and explained by the CPU
reference, and judged against the exact oracle (MPFR, \`tests/oracle/\`) on the direction that
renderer followed, at its own precision ([Exact oracle](#exact-oracle)). **decisions** = well-conditioned
decisions right / judged (which node, checker parity, each light's status; at least 64 units of
roundoff from flipping); **distances** = distances judged (one unit of roundoff moves them by at
most 2 ulps of the hit's scale S); **max ulps** = the largest distance error in ulps of S (the
bound is 8); **values** / **max units** = normals, cos θ and r² judged, and the largest error in
their own units (the bound is 8). The test records the table as properties; regenerate it alone with
\`build/tests/hexray_gpu_tests --gtest_filter='OracleSuiteTest.Every*' --gtest_output=json:oracle.json\`
and \`tools/accuracy-tables.py oracle oracle.json\`.

| family | renderer | rays | decisions | distances | max ulps | values | max units |
|---|---|---:|---:|---:|---:|---:|---:|
ORACLE
  tables oracle "$data/oracle.json"
  cat <<COST

## Cost of float64

\`hexray render scenes/lecture-demo.json --width 1920 --height 1080\`, dispatch time, five
interleaved runs of each precision in this run (\`timings_ms.render\` of \`--json\`; median, then all runs):

| precision | median ms | runs |
|---|---:|---|
COST
  tables cost "$data"/cost-*.json
} > docs/accuracy.md.tmp
mv docs/accuracy.md.tmp docs/accuracy.md  # whole or not at all
echo "wrote docs/accuracy.md"

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
} > docs/accuracy.md
echo "wrote docs/accuracy.md"

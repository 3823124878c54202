#!/usr/bin/env bash
# Measures this checkout's renderer against an earlier revision's in one run: builds REVISION in
# a temporary worktree, then runs `hexray bench` of both binaries on SCENE alternately, ROUNDS
# times each, and prints each run's lavapipe rows and the medians of their Mpix/s, so a speed-up
# is a ratio from one run rather than a figure from another day. Needs this checkout built
# (build/hexray) and git history holding REVISION.
#
# Usage: tools/bench-against.sh REVISION SCENE [BENCH OPTIONS...]
#   e.g. tools/bench-against.sh 39d3746 scenes/spheres-and-lights.json --width 960 --height 540
set -euo pipefail
cd "$(dirname "$0")/.."

revision=$1 scene=$2
shift 2
rounds=${ROUNDS:-3}
old=$(mktemp -d)
trap 'git worktree remove --force "$old/tree" >/dev/null 2>&1 || true; rm -rf "$old"' EXIT
git worktree add --detach -q "$old/tree" "$revision"
cmake -S "$old/tree" -B "$old/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build "$old/build" --parallel "$(nproc)" --target hexray >/dev/null

bench() {  # binary label [options]: the lavapipe rows of one bench run, prefixed by the label
  local binary=$1 label=$2
  shift 2
  "$binary" bench "$scene" "$@" --samples 1 --rounds 5 --reference-samples 1 2>/dev/null | tail -n +3 |
    grep '| lavapipe |' | sed "s/^/$label /"
}
results=$(mktemp)
for _ in $(seq "$rounds"); do
  bench "$old/build/hexray" "$revision" "$@" >>"$results"
  bench ./build/hexray "current" "$@" >>"$results"
done
cat "$results"
echo
echo "median Mpix/s over $rounds runs each:"
# Columns: label | scene | resolution | backend | precision | [culling |] spp | Mpix/s median ...
awk -F'|' '{
  label = $1; precision = $5; gsub(/ /, "", precision)
  culling = (NF > 15) ? $6 : ""; gsub(/ /, "", culling)
  mpix = (NF > 15) ? $8 : $7
  key = label " " precision (culling != "" ? " culling " culling : "")
  values[key] = values[key] " " mpix
} END { for (key in values) print key ":" values[key] }' "$results" | sort |
  while IFS=: read -r key list; do
    median=$(printf '%s\n' $list | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    printf '%-40s %s  (runs:%s)\n' "$key" "$median" "$list"
  done
rm -f "$results"

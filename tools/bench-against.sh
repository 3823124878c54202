#!/usr/bin/env bash
# Measures this checkout's renderer against an earlier revision's in one run: builds REVISION in
# a temporary worktree, then runs `hexray bench` of both binaries on SCENE alternately, ROUNDS
# times each, and prints each run's lavapipe rows and the medians of their Mpix/s, so a speed-up
# is a ratio from one run rather than a figure from another day. Reads the bench's --json
# documents, so REVISION must have `bench --json`. Needs this checkout built (build/hexray), git
# history holding REVISION, and ROUNDS (default 3) in the environment for fewer or more runs.
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

bench() {  # binary label [options]: one bench run's --json document, as one line labelled
  local binary=$1 label=$2 document
  shift 2
  document=$(mktemp)
  "$binary" bench "$scene" "$@" --samples 1 --rounds 5 --reference-samples 1 --json "$document" >/dev/null 2>&1
  printf '%s\t%s\n' "$label" "$(/usr/bin/python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$document")"
  rm -f "$document"
}
results=$(mktemp)
for _ in $(seq "$rounds"); do
  bench "$old/build/hexray" "$revision" "$@" >>"$results"
  bench ./build/hexray "current" "$@" >>"$results"
done
# Each run's lavapipe rows, then per label, precision and culling the median Mpix/s over the runs.
# An earlier revision without --json has no document: its runs are reported as missing.
/usr/bin/python3 - "$results" "$rounds" <<'PY'
import json, statistics, sys

runs = {}
for line in open(sys.argv[1], encoding="utf-8"):
    label, _, text = line.rstrip("\n").partition("\t")
    try:
        document = json.loads(text)
    except json.JSONDecodeError:
        print(f"{label}: no --json document (a revision older than bench --json?)")
        continue
    for scene in document["scenes"]:
        for c in scene["configurations"]:
            if c["backend"] != "lavapipe":
                continue
            precision = c["precision"]["used"] + (" (auto)" if c["precision"]["auto_pick"] else "")
            culling = "on" if c["culling"]["asked"] else "off"
            if c["culling"]["asked"] and not c["culling"]["used"]:
                culling += " (not run)"
            mpix = c["speed"]["median_mpix_s"]
            print(f"{label} | {scene['name']} | {scene['width']}x{scene['height']} | {precision} | culling {culling} | "
                  f"{c['spp']} spp | {mpix:.1f} Mpix/s median")
            runs.setdefault(f"{label} {c['precision']['used']} culling {culling}", []).append(mpix)
print()
print(f"median Mpix/s over {sys.argv[2]} runs each:")
for key in sorted(runs):
    values = runs[key]
    listed = " ".join(f"{v:.1f}" for v in values)
    print(f"{key:<40} {statistics.median_low(values):.1f}  (runs: {listed})")
PY
rm -f "$results"

#!/usr/bin/python3
"""The performance targets of docs/performance.md against the figures of one bench run, from the
CSV `hexray bench --csv` writes: ratios taken within the run, never against another day's numbers.

Usage: tools/performance-targets.py BENCH.csv
Prints a markdown table: target, figure, met or not.
"""
import csv
import math
import sys


def rows_where(rows, **fields):
    return [row for row in rows if all(row[key] == value for key, value in fields.items())]


def mpix(row):
    return float(row["median_mpix_s"])


def scene_targets(rows, scene, width, spp="1"):
    """The demo scene's targets (against the hand-written kernel) and f64 against f32 on any scene."""
    lines = []
    base = dict(scene=scene, width=width, spp=spp, backend="lavapipe")
    auto = rows_where(rows, **base, auto_pick="true")
    hand = rows_where(rows, scene=scene, width=width, spp=spp, backend="lavapipe hand-written")
    if hand:
        for culling, target in (("off", 1.0), ("on", 1.6)):
            row = [r for r in auto if r["culling_asked"] == culling][0]
            ratio = mpix(row) / mpix(hand[0])
            lines.append((f"{scene}: default renderer ({row['precision_used']} (auto)), culling {culling}, vs the hand-written "
                          f"kernel >= {target}", f"{mpix(row):.1f} / {mpix(hand[0]):.1f} = {ratio:.2f}",
                          ratio >= target))
    for culling in ("off", "on"):
        width_of = {row["precision_used"]: row for row in rows_where(rows, **base, culling_asked=culling)}
        if "f32" in width_of and "f64" in width_of:
            f32, f64 = width_of["f32"], width_of["f64"]
            ratio = mpix(f32) / mpix(f64)
            lines.append((f"{scene}: f64 no slower than 1.3x f32, culling {culling}",
                          f"{mpix(f32):.1f} / {mpix(f64):.1f} = {ratio:.2f}x slower", ratio <= 1.3))
    return lines


def certified_targets(rows, scene, width):
    """f32-certified against today's f32 in the same run: at least 0.9x its speed, every spp and culling."""
    lines = []
    for spp in sorted({row["spp"] for row in rows if row["scene"] == scene and row["width"] == width}, key=int):
        for culling in ("off", "on"):
            by_precision = {row["precision_used"]: row
                            for row in rows_where(rows, scene=scene, width=width, spp=spp, backend="lavapipe",
                                                  culling_asked=culling)}
            if "f32" in by_precision and "f32-certified" in by_precision:
                f32, certified = by_precision["f32"], by_precision["f32-certified"]
                ratio = mpix(certified) / mpix(f32)
                lines.append((f"{scene}: f32-certified >= 0.9x f32, {spp} spp, culling {culling}",
                              f"{mpix(certified):.1f} / {mpix(f32):.1f} = {ratio:.2f} "
                              f"(f64 pass: {100 * float(certified['f64_pass_pixel_share']):.2f} % of pixels, "
                              f"{100 * float(certified['f64_pass_vector_share']):.2f} % of vectors)",
                              ratio >= 0.9))
    return lines


def curve_targets(rows):
    lines = []
    curve = [row for row in rows if row["spheres"] and row["spp"] == "1"]
    counts = sorted({int(row["spheres"]) for row in curve})
    cost = {}
    for count in counts:
        at = [row for row in curve if int(row["spheres"]) == count]
        lavapipe = [row for row in at if row["backend"] == "lavapipe"]
        gpu = [row for row in lavapipe if row["precision_used"] == "f32"]
        naive = [row for row in lavapipe if row["precision_used"] == "f32-naive"]
        embree = [row for row in at if row["backend"].startswith("embree")]
        if not gpu:
            lines.append((f"{count} spheres: lavapipe >= 1.0x Embree's fastest row", "not measured", False))
            continue
        cost[count] = float(gpu[0]["core_ns_per_pixel"])
        if embree:
            best = max(mpix(row) for row in embree)
            ratio = mpix(gpu[0]) / best
            lines.append((f"{count} spheres: lavapipe >= 1.0x Embree's fastest row",
                          f"{mpix(gpu[0]):.1f} / {best:.1f} = {ratio:.2f}", ratio >= 1.0))
        # f32-naive's mismatches are what the textbook formulas cost, measured, not a defect.
        mismatches = [row["topology_mismatches"] for row in at if row["topology_mismatches"] and row not in naive]
        lines.append((f"{count} spheres: 0 topology mismatches on every backend but f32-naive", ", ".join(mismatches),
                      all(m == "0" for m in mismatches)))
        slower = mpix(gpu[0]) / mpix(naive[0]) if naive else None
        lines.append((f"{count} spheres: f32-naive no slower than 3x f32",
                      f"{mpix(gpu[0]):.1f} / {mpix(naive[0]):.1f} = {slower:.2f}x slower" if naive
                      else "not measured (see the notes under the curve)", bool(naive) and slower <= 3.0))
        if count == 100000:
            lines.append(("100k spheres: lavapipe >= 10 Mpix/s", f"{mpix(gpu[0]):.1f}", mpix(gpu[0]) >= 10))
    past = [count for count in sorted(cost) if count >= 100]
    for low, high in zip(past, past[1:]):
        decades = math.log10(high / low)
        growth = (cost[high] - cost[low]) / decades
        lines.append((f"core-ns per pixel from {low} to {high} spheres grows <= 100 per decade",
                      f"{cost[low]:.0f} -> {cost[high]:.0f}: {growth:+.0f} per decade", growth <= 100))
    return lines


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    lines = []
    for scene, width in sorted({(row["scene"], row["width"]) for row in rows if not row["spheres"]}):
        lines += scene_targets(rows, scene, width)
        lines += certified_targets(rows, scene, width)
    lines += curve_targets(rows)
    print("| target | figure (this run) | met |")
    print("|---|---|:-:|")
    for target, figure, met in lines:
        print(f"| {target} | {figure} | {'yes' if met else '**no**'} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

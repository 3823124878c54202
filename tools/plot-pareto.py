#!/usr/bin/python3
"""Speed against error, from `hexray bench --csv`: one panel per scene, time per frame
(median, log scale) against the precision error (RMSE against the CPU reference at the same
sample count, unambiguous pixels, levels), with the non-dominated configurations joined as the
Pareto frontier. Rows of the sphere curve
(`--spheres`, the `spheres` column set) get two panels of their own: Mpix/s against the
sphere count (log-log), and core-ns per pixel against it (log x, so cost growing like log N
shows as a straight line).

Usage: tools/plot-pareto.py BENCH.csv OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def pareto(points):
    """The points no other point beats in both time and error, sorted by time."""
    frontier = []
    for time, error, label in sorted(points):
        if not frontier or error < frontier[-1][1]:
            frontier.append((time, error, label))
    return frontier


def precision(row):
    """The precision that ran, marked where it is the one `auto` picks."""
    return row["precision_used"] + (" (auto)" if row["auto_pick"] == "true" else "")


def pareto_panel(axis, scene, rows):
    points = []
    for row in rows:
        time = float(row["median_render_ms"])
        error = float(row["precision_rmse_levels"])
        culled = " culled" if row["culling_used"] == "on" else ""
        label = f'{row["backend"]} {precision(row)}{culled} {row["spp"]}spp'
        points.append((time, error, label))
        marker = "s" if row["backend"] == "cpu-reference" else "^" if row["backend"].startswith("embree") else (
            "D" if "hand-written" in row["backend"] else "o")
        axis.scatter(time, error, marker=marker)
        axis.annotate(label, (time, error), fontsize=7, xytext=(4, 3), textcoords="offset points")
    frontier = pareto(points)
    axis.plot([p[0] for p in frontier], [p[1] for p in frontier], "k--", linewidth=0.8, label="Pareto frontier")
    axis.set_title(f'{scene} ({rows[0]["width"]}x{rows[0]["height"]})')
    axis.set_xscale("log")
    axis.set_xlabel("render time per frame, ms (median)")
    axis.set_yscale("symlog", linthresh=0.01)
    axis.set_ylabel("precision error: RMSE against the CPU reference, same spp, 8-bit levels")
    axis.grid(True, which="both", linewidth=0.3)
    axis.legend(fontsize=8)


def curve_panels(speed_axis, cost_axis, rows):
    series = {}
    for row in rows:
        key = f'{row["backend"]} {precision(row)} {row["spp"]}spp'
        series.setdefault(key, []).append(
            (int(row["spheres"]), float(row["median_mpix_s"]), float(row["core_ns_per_pixel"])))
    for key, points in sorted(series.items()):
        points.sort()
        counts = [p[0] for p in points]
        speed_axis.plot(counts, [p[1] for p in points], "o-", label=key)
        cost_axis.plot(counts, [p[2] for p in points], "o-", label=key)
    resolution = f'{rows[0]["width"]}x{rows[0]["height"]}'
    speed_axis.set_title(f"random spheres over a plane, {resolution}: speed")
    speed_axis.set_yscale("log")
    speed_axis.set_ylabel("Mpix/s (median)")
    cost_axis.set_title(f"random spheres over a plane, {resolution}: cost per pixel")
    cost_axis.set_ylabel("core-ns per pixel (render time x threads / pixels)")
    for axis in (speed_axis, cost_axis):
        axis.set_xscale("log")
        axis.set_xlabel("spheres")
        axis.grid(True, which="both", linewidth=0.3)
        axis.legend(fontsize=8)


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    scene_rows = [row for row in rows if not row.get("spheres")]
    curve_rows = [row for row in rows if row.get("spheres")]
    scenes = sorted({row["scene"] for row in scene_rows})
    panels = len(scenes) + (2 if curve_rows else 0)
    figure, axes = plt.subplots(1, panels, figsize=(6.5 * panels, 5), squeeze=False)
    for axis, scene in zip(axes[0], scenes):
        pareto_panel(axis, scene, [row for row in scene_rows if row["scene"] == scene])
    if curve_rows:
        curve_panels(axes[0][len(scenes)], axes[0][len(scenes) + 1], curve_rows)
    figure.tight_layout()
    figure.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

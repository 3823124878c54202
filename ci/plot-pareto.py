#!/usr/bin/python3
"""Speed against error, from `hexray bench --csv`: one panel per scene, time per frame
(median, log scale) against RMSE to the converged reference (levels), with the
non-dominated configurations joined as the Pareto frontier.

Usage: ci/plot-pareto.py BENCH.csv OUT.png
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


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = sorted({row["scene"] for row in rows})
    figure, axes = plt.subplots(1, len(scenes), figsize=(6.5 * len(scenes), 5), squeeze=False)
    for axis, scene in zip(axes[0], scenes):
        points = []
        for row in rows:
            if row["scene"] != scene:
                continue
            time = float(row["median_render_ms"])
            error = float(row["rmse_levels"])
            label = f'{row["backend"]} {row["precision"]} {row["spp"]}spp'
            points.append((time, error, label))
            marker = "s" if row["backend"] == "cpu-reference" else "o"
            axis.scatter(time, error, marker=marker)
            axis.annotate(label, (time, error), fontsize=7, xytext=(4, 3), textcoords="offset points")
        frontier = pareto(points)
        axis.plot([p[0] for p in frontier], [p[1] for p in frontier], "k--", linewidth=0.8, label="Pareto frontier")
        width, height = next((r["width"], r["height"]) for r in rows if r["scene"] == scene)
        axis.set_title(f"{scene} ({width}x{height})")
        axis.set_xscale("log")
        axis.set_xlabel("render time per frame, ms (median)")
        axis.set_ylabel("RMSE against the converged reference, 8-bit levels")
        axis.grid(True, which="both", linewidth=0.3)
        axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

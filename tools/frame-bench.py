#!/usr/bin/env python3
"""A whole frame, process against process: `hexray render` of a random-sphere scene file to a
PNG (load, plan, upload, render, write), in the precision auto picks and in f32, against
tests/bench/embree_frame.cpp (load, build, trace, write with Embree at its best), alternating, in
one run. Prints each program's median wall time and peak resident memory (from wait4) and their
ratios, as markdown. Needs build/hexray and build/tests/hexray_embree_frame (Embree 3:
ci/build.sh --bench), which it builds. Usage:

    tools/frame-bench.py [--spheres 1000000] [--rounds 3] [--width 1920] [--height 1080]

The first round of each program is a cold start (hexray's kernel cache and llvmpipe's shader
cache empty); it is reported apart and left out of the medians.
"""
import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
EMBREE = "Embree frame"


def run_measured(command, env):
    """Wall seconds and peak resident MiB of one process; its output if it fails."""
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    output = process.stdout.read()
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.monotonic() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        sys.exit(f"{' '.join(map(str, command))} failed ({process.returncode}):\n{output.decode()}")
    return seconds, usage.ru_maxrss / 1024.0, output.decode().strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--spheres", type=int, default=1000000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--width", type=int, default=1920)
    parser.add_argument("--height", type=int, default=1080)
    args = parser.parse_args()

    built = subprocess.run(["cmake", "--build", "build", "--parallel", str(os.cpu_count()), "--target", "hexray",
                            "hexray_embree_frame"], cwd=ROOT, stdout=subprocess.DEVNULL)
    if built.returncode != 0:
        sys.exit("frame-bench: building hexray and hexray_embree_frame failed (the latter needs Embree 3: "
                 "bash ci/build.sh --bench)")
    icd = sorted(pathlib.Path("/usr/share/vulkan/icd.d").glob("lvp_icd.*.json"))[0]
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        env = dict(os.environ, VK_DRIVER_FILES=str(icd), VK_ICD_FILENAMES=str(icd),
                   XDG_CACHE_HOME=str(work / "cache"))
        scene = work / "scene.json"
        subprocess.run([sys.executable, ROOT / "tools/make-spheres-scene.py", str(args.spheres), scene], check=True)
        size = ["--width", str(args.width), "--height", str(args.height)]
        render = [ROOT / "build/hexray", "render", scene, "-o", work / "hexray.png"] + size
        programs = {
            "hexray render (lavapipe, precision auto)": render,
            "hexray render (lavapipe, --precision f32: Embree's float)": render + ["--precision", "f32"],
            EMBREE: [ROOT / "build/tests/hexray_embree_frame", scene, work / "embree.png"] + size,
        }
        runs = {name: [] for name in programs}
        for _ in range(args.rounds + 1):
            for name, command in programs.items():
                runs[name].append(run_measured(command, env))

    print(f"{args.spheres} spheres, {args.width}x{args.height}, {os.cpu_count()} cores, "
          f"median of {args.rounds} warm rounds (a cold first round apart)\n")
    print("| program | wall s (median) | peak MiB (median) | cold wall s | last run's phases |")
    print("|---|---:|---:|---:|---|")
    medians = {}
    for name, measured in runs.items():
        wall = statistics.median(m[0] for m in measured[1:])
        peak = statistics.median(m[1] for m in measured[1:])
        medians[name] = (wall, peak)
        phases = measured[-1][2].splitlines()[-1].split(" — ")[-1] if measured[-1][2] else ""
        print(f"| {name} | {wall:.2f} | {peak:.0f} | {measured[0][0]:.2f} | {phases} |")
    embree_wall, embree_peak = medians.pop(EMBREE)
    print()
    for name, (wall, peak) in medians.items():
        print(f"{name} / Embree: wall {wall / embree_wall:.2f}x, peak memory {peak / embree_peak:.2f}x")


if __name__ == "__main__":
    main()

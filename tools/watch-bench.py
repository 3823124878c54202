#!/usr/bin/python3
"""The edit loop of `hexray watch`, timed as a person editing the demo scene would feel it.

In one run, with the kernel cache and Mesa's shader cache in a fresh directory (XDG_CACHE_HOME):
1. `hexray watch` on a copy of scenes/lecture-demo.json at 800x600. Each edit is saved as an
   editor saves, by writing another file and renaming it over the scene; the latency is from the
   rename to the new PNG on disk (its inode changes: the output is replaced atomically). A value
   edit changes the sphere's radius (a value never rendered before); a structural edit adds a
   sphere. After each edit the script waits for the background tier-up (the specialised kernel's
   image) and reports it too, from the same save.
2. The first render of a scene never seen (both caches empty): `hexray render` (today's:
   glslang, then the driver's compile of the specialised kernel) against `hexray watch --frames 1`
   (its first frame tiered: the kernel reading values from a buffer) and the data-driven kernel
   (prebuilt, no glslang), each from the process's start to the PNG on disk, interleaved; and the
   same with a scene of a structure seen before (caches warm from it) but values never seen.
Prints a table of medians. The machine's load shows in every figure: run it on an idle machine.

Usage: tools/watch-bench.py [--hexray build/hexray] [--edits 10] [--firsts 5]
"""

import argparse
import copy
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def lavapipe_environment(cache_home):
    environment = dict(os.environ)
    icds = sorted(Path("/usr/share/vulkan/icd.d").glob("lvp_icd.*.json"))
    if icds:
        environment["VK_DRIVER_FILES"] = environment["VK_ICD_FILENAMES"] = str(icds[0])
    environment["XDG_CACHE_HOME"] = str(cache_home)
    environment.pop("MESA_SHADER_CACHE_DISABLE", None)
    environment.pop("MESA_SHADER_CACHE_DIR", None)
    return environment


def save_by_rename(path, scene):
    """Writes the scene as an editor does; returns the time of the rename."""
    temporary = path.with_name("." + path.name + ".swp")
    temporary.write_text(json.dumps(scene))
    start = time.monotonic()
    os.rename(temporary, path)
    return start


def inode(path):
    try:
        return os.stat(path).st_ino
    except FileNotFoundError:
        return None


def wait_for_new_file(path, old_inode, timeout=60.0):
    """The time the file at `path` is replaced (polled in a tight loop)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        current = inode(path)
        if current is not None and current != old_inode:
            return time.monotonic(), current
        time.sleep(0.0002)
    raise SystemExit(f"watch-bench: {path} was not rewritten within {timeout} s")


class Lines:
    """The lines a process prints, read on a thread, waited for by what they contain."""

    def __init__(self, stream):
        self.lines, self.condition = [], threading.Condition()
        threading.Thread(target=self._read, args=(stream,), daemon=True).start()

    def _read(self, stream):
        for line in stream:
            with self.condition:
                self.lines.append((time.monotonic(), line.rstrip("\n")))
                self.condition.notify_all()

    def wait_for(self, text, after, timeout=120.0):
        """The time of the first line from index `after` on that contains `text`, and its index."""
        with self.condition:
            deadline = time.monotonic() + timeout
            while True:
                for index in range(after, len(self.lines)):
                    if text in self.lines[index][1]:
                        return self.lines[index][0], index + 1
                if not self.condition.wait(max(0.0, deadline - time.monotonic())):
                    raise SystemExit(f"watch-bench: no line with {text!r}; last: {self.lines[-3:]}")


def extra_sphere(number):
    return {"geometry": {"type": "sphere", "center": [15 + 12 * number, 15, 10 * number], "radius": 6},
            "shader": "ball"}


def edit_loop(hexray, work, base, edits):
    """Latencies (ms) of value and structural edits, to the first image and to the tier-up's."""
    scene_path, output = work / "scene.json", work / "out.png"
    scene_path.write_text(json.dumps(base))
    process = subprocess.Popen([hexray, "watch", str(scene_path), "-o", str(output)], stdout=subprocess.PIPE,
                               stderr=sys.stderr, text=True, env=lavapipe_environment(work / "cache"))
    lines = Lines(process.stdout)
    _, seen = lines.wait_for("specialised", 0)  # the first render and its tier-up
    results = {"value": ([], []), "structure": ([], [])}
    scene = copy.deepcopy(base)
    for kind in ("value", "structure"):
        for number in range(edits):
            if kind == "value":
                scene["nodes"][1]["geometry"]["radius"] = 10 + 0.05 * (number + 1)
            else:
                scene["nodes"].append(extra_sphere(number))
            old = inode(output)
            saved = save_by_rename(scene_path, scene)
            written, _ = wait_for_new_file(output, old)
            tiered, seen = lines.wait_for("kernel specialised", seen)
            results[kind][0].append(1000 * (written - saved))
            results[kind][1].append(1000 * (tiered - saved))
    process.terminate()
    if process.wait(timeout=30) != 0:
        raise SystemExit(f"watch-bench: hexray watch exited with {process.returncode}")
    return results


def first_render(hexray, work, scene, command, warm_from=None):
    """Milliseconds from starting `command` to its PNG on disk, caches empty (or warm from a scene)."""
    run = Path(tempfile.mkdtemp(dir=work))
    environment = lavapipe_environment(run / "cache")
    if warm_from is not None:
        (run / "warm.json").write_text(json.dumps(warm_from))
        subprocess.run([hexray, "-q", *command(run / "warm.json", run / "warm.png")], check=True, env=environment)
    (run / "scene.json").write_text(json.dumps(scene))
    output = run / "out.png"
    start = time.monotonic()
    process = subprocess.Popen([hexray, "-q", *command(run / "scene.json", output)], env=environment)
    written, _ = wait_for_new_file(output, None)
    if process.wait(timeout=120) != 0:
        raise SystemExit(f"watch-bench: {command(run / 'scene.json', output)} failed")
    shutil.rmtree(run)
    return 1000 * (written - start)


FIRST_RENDERS = {
    "render (today: specialised kernel)": lambda scene, out: ["render", str(scene), "-o", str(out)],
    "watch, first frame (tiered: values from a buffer)": lambda scene, out: ["watch", str(scene), "-o", str(out),
                                                                            "--frames", "1"],
    "watch --kernel data-driven, first frame": lambda scene, out: ["watch", str(scene), "-o", str(out), "--frames",
                                                                   "1", "--kernel", "data-driven"],
}


def first_renders(hexray, work, base, rounds):
    """Medians per way and cache state, the ways interleaved round by round."""
    other_values = copy.deepcopy(base)
    other_values["nodes"][1]["geometry"]["radius"] = 11.5
    other_values["lights"][0]["intensity"] = 9000
    times = {}
    for _ in range(rounds):
        for name, command in FIRST_RENDERS.items():
            times.setdefault(("never seen (caches empty)", name), []).append(first_render(hexray, work, base, command))
            times.setdefault(("structure seen, values not", name), []).append(
                first_render(hexray, work, base, command, warm_from=other_values))
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--hexray", default=str(ROOT / "build" / "hexray"))
    parser.add_argument("--edits", type=int, default=10, help="edits of each kind")
    parser.add_argument("--firsts", type=int, default=5, help="rounds of first renders")
    arguments = parser.parse_args()
    base = json.loads((ROOT / "scenes" / "lecture-demo.json").read_text())
    base["image"].update(width=800, height=600)
    work = Path(tempfile.mkdtemp(prefix="hexray-watch-bench-"))
    try:
        edits = edit_loop(arguments.hexray, work, base, arguments.edits)
        firsts = first_renders(arguments.hexray, work, base, arguments.firsts)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"\n`hexray watch` on lecture-demo.json at 800x600: medians of {arguments.edits} edits each, ms\n")
    print("| edit | save to new PNG | save to the tier-up's PNG |\n|---|---:|---:|")
    for kind, label in (("value", "value (the sphere's radius)"), ("structure", "structural (a sphere added)")):
        first, tiered = edits[kind]
        print(f"| {label} | {statistics.median(first):.1f} | {statistics.median(tiered):.1f} |")
    print(f"\nFirst render, process start to PNG on disk: medians of {arguments.firsts} rounds, ms\n")
    print("| caches | way | ms |\n|---|---|---:|")
    for (state, name), values in times_sorted(firsts):
        print(f"| {state} | {name} | {statistics.median(values):.1f} |")


def times_sorted(times):
    return sorted(times.items(), key=lambda item: item[0][0])


if __name__ == "__main__":
    main()

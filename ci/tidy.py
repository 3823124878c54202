#!/usr/bin/env python3
"""clang-tidy (.clang-tidy) over host/, one translation unit per layer; any finding fails.

Each layer's sources are read as one file that includes them all, so the heavy headers (Vulkan-Hpp,
nlohmann/json, CLI11) are parsed once per layer rather than once per source: the same checks on the
same code in a fraction of the time. It also means no two sources of a layer may define the same
internal name, which keeps helpers from being copied between files.

Usage: ci/tidy.py BUILD_DIR (a configured build with compile_commands.json, as ci/build.sh makes).
"""
import concurrent.futures
import json
import os
import pathlib
import re
import subprocess
import sys


def layer_units(build_dir, out_dir):
    """Writes one unity source per layer and its compile command; returns the unity sources."""
    commands = json.loads((build_dir / "compile_commands.json").read_text())
    layers = {}
    for entry in commands:
        # A source of its own, or a unity source that includes several (HEXRAY_UNITY_BUILD).
        target = re.search(r"CMakeFiles/(hexray_\w+)\.dir/(?:host|Unity)/", entry["command"])
        if target:
            layers.setdefault(target.group(1), []).append(entry)
    units = []
    for layer, entries in sorted(layers.items()):
        # A source compiled apart has options of its own (build_version.cpp's version defines): the
        # layer's unit takes its command, since the unity sources' adds nothing it lacks.
        entries.sort(key=lambda e: "/Unity/" in e["command"])
        unit = out_dir / f"{layer}.cpp"
        unit.write_text("".join(f'#include "{e["file"]}"\n' for e in entries))
        command = entries[0]["command"]
        # GCC's precompiled header and GCC-only warning options mean nothing to clang.
        command = re.sub(r" -include \S*cmake_pch\.hxx| -Winvalid-pch| -Werror\S*| -Wno-error=\S+", "", command)
        command = re.sub(r" -o \S+ -c \S+", f" -c {unit}", command)
        units.append({"directory": entries[0]["directory"], "command": command, "file": str(unit)})
    (out_dir / "compile_commands.json").write_text(json.dumps(units, indent=1))
    return [u["file"] for u in units]


def tidy(out_dir, unit):
    run = subprocess.run(["clang-tidy-14", "-p", str(out_dir), "--quiet", unit], capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


def main():
    build_dir = pathlib.Path(sys.argv[1]).resolve()
    out_dir = build_dir / "tidy"
    out_dir.mkdir(exist_ok=True)
    units = layer_units(build_dir, out_dir)
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
        for unit, (code, output) in zip(units, pool.map(lambda u: tidy(out_dir, u), units)):
            if code != 0:
                failed += 1
                print(f"clang-tidy: {pathlib.Path(unit).stem}:\n{output}")
    print(f"clang-tidy: {len(units)} layers, {failed} with findings")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Writes a scene file of many random point lights (and optionally random spheres), compactly,
for measuring how hexray plans, loads and renders scenes with many lights:

    python3 tools/make-lights-scene.py 100000 0 lights.json          # 100k lights, nothing to light
    python3 tools/make-lights-scene.py 100000 100 lights.json        # and 100 spheres
    python3 tools/make-lights-scene.py 2000 20 lights.json --floor   # a checkered floor under them

The lights hang at heights of 10 to 30 over the square the spheres (radii 0.5 to 2.5) stand on,
their intensities summing to about one bright light's, so the image neither saturates nor goes
black. Every pixel that shows a surface costs a shading step per light on either backend, so
without --floor most pixels are background and the figures are the planning's and loading's.
The same arguments give the same file.
"""
import argparse
import math
import random


def scene_text(lights, spheres, floor, width, height, seed):
    rng = random.Random(seed)
    side = 4.0 * math.sqrt(max(spheres, 1)) + 40.0
    intensity = 0.8 * side * side / max(lights, 1)
    parts = [
        f'{{"image":{{"width":{width},"height":{height}}},'
        f'"camera":{{"position":[0,{0.45 * side:.3f},{-0.55 * side:.3f}],"pitch":-35,"fov":90}},'
        '"background":[0.05,0.07,0.12],"ambient":[0.05,0.05,0.05],'
        '"shaders":{"floor":{"type":"checker","color1":[0.8,0.8,0.8],"color2":[0.2,0.2,0.25],"size":4},'
        '"red":{"type":"lambert","color":[0.8,0.2,0.2]},"blue":{"type":"lambert","color":[0.2,0.3,0.9]}},'
        '"lights":['
    ]
    for i in range(lights):
        x = rng.uniform(-0.5 * side, 0.5 * side)
        y = rng.uniform(10.0, 30.0)
        z = rng.uniform(0.0, side)
        parts.append(f'{"," if i else ""}{{"position":[{x:.3f},{y:.3f},{z:.3f}],"intensity":{intensity:.4g}}}')
    parts.append('],"nodes":[' + ('{"geometry":{"type":"plane","y":0},"shader":"floor"}' if floor else ""))
    for i in range(spheres):
        radius = rng.uniform(0.5, 2.5)
        x = rng.uniform(-0.5 * side, 0.5 * side)
        z = rng.uniform(0.0, side)
        parts.append(f'{"," if floor or i else ""}{{"geometry":{{"type":"sphere","center":[{x:.3f},{radius:.3f},{z:.3f}],'
                     f'"radius":{radius:.3f}}},"shader":"{rng.choice(["red", "blue"])}"}}')
    parts.append("]}\n")
    return "".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("lights", type=int)
    parser.add_argument("spheres", type=int)
    parser.add_argument("out")
    parser.add_argument("--floor", action="store_true", help="a checkered plane at y = 0")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=180)
    args = parser.parse_args()
    with open(args.out, "w", encoding="ascii") as out:
        out.write(scene_text(args.lights, args.spheres, args.floor, args.width, args.height, args.seed))


if __name__ == "__main__":
    main()

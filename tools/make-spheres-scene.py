#!/usr/bin/env python3
"""Writes a scene file of N random spheres, compactly (one line, 3 decimals), for measuring how
hexray loads, builds and renders large scenes:

    python3 tools/make-spheres-scene.py 1000000 big.json

The layout follows makeRandomSpheresScene (host/scene/random_spheres.h): a checkered floor,
spheres of radii 0.5 to 2.5 over a square whose side grows as sqrt(N), two lights, a camera
above and behind the square. Python's own generator places them, so the spheres are not the
C++ generator's; the same N and seed give the same file.
"""
import math
import random
import sys


def scene_text(count, seed):
    rng = random.Random(seed)
    side = 4.0 * math.sqrt(count) + 10.0
    head = (
        '{"image":{"width":320,"height":180},'
        f'"camera":{{"position":[0,{0.45 * side:.3f},{-0.55 * side:.3f}],"pitch":-35,"fov":90}},'
        '"background":[0.05,0.07,0.12],"ambient":[0.1,0.1,0.1],'
        f'"lights":[{{"position":[{-0.3 * side:.3f},{0.8 * side:.3f},{0.1 * side:.3f}],'
        f'"intensity":{0.6 * side * side:.3f}}},'
        f'{{"position":[{0.4 * side:.3f},{0.5 * side:.3f},{0.7 * side:.3f}],"color":[0.9,0.8,0.6],'
        f'"intensity":{0.3 * side * side:.3f}}}],'
        '"shaders":{"floor":{"type":"checker","color1":[0.8,0.8,0.8],"color2":[0.2,0.2,0.25],"size":4},'
        '"red":{"type":"lambert","color":[0.8,0.2,0.2]},"green":{"type":"lambert","color":[0.2,0.8,0.3]},'
        '"blue":{"type":"lambert","color":[0.2,0.3,0.9]},'
        '"checkered":{"type":"checker","color1":[0.9,0.9,0.2],"color2":[0.1,0.1,0.1],"size":30},'
        '"glow":{"type":"constant","color":[1,0.9,0.7]}},'
        '"nodes":[{"geometry":{"type":"plane","y":0},"shader":"floor"}'
    )
    shaders = ["red", "green", "blue", "checkered", "glow"]
    parts = [head]
    for _ in range(count):
        radius = rng.uniform(0.5, 2.5)
        x = rng.uniform(-0.5 * side, 0.5 * side)
        z = rng.uniform(0.0, side)
        y = radius + (0.0 if rng.random() < 0.75 else rng.uniform(0.0, 4.0))
        parts.append(f',{{"geometry":{{"type":"sphere","center":[{x:.3f},{y:.3f},{z:.3f}],"radius":{radius:.3f}}},'
                     f'"shader":"{rng.choice(shaders)}"}}')
    parts.append("]}\n")
    return "".join(parts)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: make-spheres-scene.py COUNT OUT.json [SEED]")
    count = int(sys.argv[1])
    seed = int(sys.argv[3]) if len(sys.argv) == 4 else 1
    with open(sys.argv[2], "w", encoding="ascii") as out:
        out.write(scene_text(count, seed))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Hostile version-2 scenes for the 3-D stages' scale and edge cases (docs/world.md, "At scale").

    scripts/hostile_scenes.py OUT_DIR [--soup-triangles N] [--fan-triangles N]

writes, each from a fixed seed (the same bytes on every run):

  soup.json        N (default 200,000) random small triangles in a 4 x 4 x 4 box, 128 x 96:
                   deep overlap, millions of overlapping pairs, a few thousand visible pieces;
  fan.json         N (default 100,000) coplanar triangles sharing one vertex, fanned at random
                   angles inside one pixel, 64 x 64: every pair overlaps, none is nearer;
  point-light.json a point light at the centroid of a face (1/d^2 at d = 0);
  huge.json        a square at z = -1e100 with x, y = +-1e99 (inside the documented range).

The timing commands and the figures measured with them are in docs/world.md, "At scale".
"""
import json
import math
import os
import random
import sys


def soup(n, seed=20260401):
    rng = random.Random(seed)
    vertices = []
    faces = []
    for i in range(n):
        cx, cy, cz = (rng.uniform(-2.0, 2.0) for _ in range(3))
        # Triangles about 0.05 world units (about a pixel at this distance) across.
        for _ in range(3):
            vertices.append([round(cx + rng.uniform(-0.04, 0.04), 6),
                             round(cy + rng.uniform(-0.04, 0.04), 6),
                             round(cz + rng.uniform(-0.04, 0.04), 6)])
        faces.append({"loop": [3 * i, 3 * i + 1, 3 * i + 2],
                      "reflectance": round(rng.uniform(0.1, 0.9), 3)})
    return {
        "version": 2, "width": 128, "height": 96, "background": 0.0,
        "metadata": {"generator": "hostile_scenes.py soup", "triangles": str(n),
                     "seed": str(seed)},
        "camera": {"eye": [0.0, 0.0, 8.0], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40},
        "objects": [{"name": "soup", "closed": False, "vertices": vertices, "faces": faces}],
    }


def fan(n, seed=20260402):
    rng = random.Random(seed)
    # One pixel at 64 x 64 with fov 40 at distance 5 is about 0.057 world units wide: the fan's
    # radius of 0.02 keeps every triangle inside the pixel around the image centre.
    radius = 0.02
    vertices = [[0.0, 0.0, 0.0]]
    faces = []
    for i in range(n):
        a = rng.uniform(0.0, 2.0 * math.pi)
        span = rng.uniform(0.01, 1.0)
        for t in (a, a + span):
            vertices.append([radius * math.cos(t), radius * math.sin(t), 0.0])
        faces.append({"loop": [0, 1 + 2 * i, 2 + 2 * i],
                      "reflectance": round(rng.uniform(0.1, 0.9), 3)})
    return {
        "version": 2, "width": 64, "height": 64, "background": 0.0,
        "metadata": {"generator": "hostile_scenes.py fan", "triangles": str(n),
                     "seed": str(seed)},
        "camera": {"eye": [0.003, 0.002, 5.0], "target": [0.003, 0.002, 0.0], "fov_y_deg": 40},
        "objects": [{"name": "fan", "closed": False, "vertices": vertices, "faces": faces}],
    }


def point_light():
    return {
        "version": 2, "width": 32, "height": 32, "background": 0.0,
        "camera": {"eye": [0.3, 2.0, 3.0], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40},
        "lights": [{"type": "point", "position": [0.0, 0.0, 0.0], "intensity": 1.0}],
        "objects": [{"name": "floor", "closed": False,
                     "vertices": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]],
                     "faces": [{"loop": [3, 2, 1, 0]}]}],
    }


def huge():
    return {
        "version": 2, "width": 32, "height": 32, "background": 0.0,
        "camera": {"eye": [0.0, 0.0, 0.0], "target": [0.0, 0.0, -1.0], "fov_y_deg": 40},
        "objects": [{"name": "far", "closed": False,
                     "vertices": [[-1e99, -1e99, -1e100], [1e99, -1e99, -1e100],
                                  [1e99, 1e99, -1e100], [-1e99, 1e99, -1e100]],
                     "faces": [{"loop": [0, 1, 2, 3]}]}],
    }


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(argv) >= 2 else 2)
    out = argv[1]
    if out.startswith("-"):
        sys.exit(f"hostile_scenes.py: the first argument is the output directory, not {out!r}")
    soup_n, fan_n = 200000, 100000
    args = argv[2:]
    while args:
        if len(args) < 2:
            sys.exit(f"hostile_scenes.py: {args[0]} needs a number")
        key, value = args[0], int(args[1])
        args = args[2:]
        if key == "--soup-triangles":
            soup_n = value
        elif key == "--fan-triangles":
            fan_n = value
        else:
            sys.exit(f"unknown option {key}")
    os.makedirs(out, exist_ok=True)
    for name, scene in (("soup", soup(soup_n)), ("fan", fan(fan_n)),
                        ("point-light", point_light()), ("huge", huge())):
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(scene, f, separators=(",", ":"))


if __name__ == "__main__":
    main(sys.argv)

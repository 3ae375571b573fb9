#!/usr/bin/env python3
"""Writes a scene of many small objects for editor measurements into OUT_DIR (never into
the repo): many_objects.json, N spheres (20,000 by default) on a ground quad in a square
grid, sharing 64 toon and diffuse materials in turn, lit by a sun and a point light, at
960x540 with outlines. It measures what an edit costs when the document is large but the
edit small (docs/benchmarks.md, "Editor").
usage: scripts/make_many_objects.py OUT_DIR [--objects 20000] [--materials 64]"""
import argparse
import colorsys
import json
import math
import os


def material(i, count):
    r, g, b = colorsys.hsv_to_rgb(i / count, 0.55, 0.85)
    color = [round(r, 3), round(g, 3), round(b, 3)]
    if i % 2:
        return {"name": f"m{i}", "type": "diffuse", "albedo": color}
    return {"name": f"m{i}", "type": "toon", "color": color, "shadow_color": [0.35, 0.3, 0.5],
            "threshold": 0.45, "environment": 1}


def scene(objects, materials):
    side = math.ceil(math.sqrt(objects))
    spacing = 1.0
    extent = side * spacing
    doc = {
        "format": "inkray-scene",
        "version": 1,
        # Near the front rows, looking over the rest to the far edge.
        "camera": {"look_from": [0, 7, extent * 0.5 + 6], "look_at": [0, 0, extent * 0.2], "up": [0, 1, 0],
                   "vfov": 40},
        "render": {"width": 960, "height": 540, "spp": 64, "max_depth": 4},
        "outlines": {"enabled": True, "width": 1.5, "silhouette": {"enabled": True, "color": [0.05, 0.05, 0.08]}},
        "environment": {"type": "gradient", "zenith": [0.12, 0.2, 0.42], "horizon": [0.3, 0.3, 0.38],
                        "nadir": [0.05, 0.05, 0.05]},
        "materials": [material(i, materials) for i in range(materials)]
        + [{"name": "ground", "type": "diffuse", "albedo": [0.6, 0.6, 0.55]}],
        "objects": [{"name": "ground", "material": "ground",
                     "shape": {"type": "quad", "corner": [-extent, 0, -extent], "edge_u": [0, 0, 2 * extent],
                               "edge_v": [2 * extent, 0, 0]}}],
        "lights": [{"name": "sun", "type": "directional", "direction": [-0.6, -1, -0.45],
                    "color": [1, 0.96, 0.88], "intensity": 4},
                   {"name": "fill", "type": "point", "position": [-extent * 0.3, extent * 0.2, extent * 0.3],
                    "color": [0.8, 0.85, 1], "intensity": extent * extent * 0.02}],
    }
    for k in range(objects):
        x = (k % side - (side - 1) / 2) * spacing
        z = (k // side - (side - 1) / 2) * spacing
        doc["objects"].append({"name": f"ball{k}", "material": f"m{k % materials}",
                               "shape": {"type": "sphere", "center": [round(x, 4), 0.35, round(z, 4)],
                                         "radius": 0.35}})
    return doc


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out_dir")
    parser.add_argument("--objects", type=int, default=20000)
    parser.add_argument("--materials", type=int, default=64)
    args = parser.parse_args()
    if args.objects < 1 or args.materials < 1:
        parser.error("--objects and --materials must be at least 1")
    os.makedirs(args.out_dir, exist_ok=True)
    path = os.path.join(args.out_dir, "many_objects.json")
    with open(path + ".tmp", "w") as f:
        json.dump(scene(args.objects, args.materials), f, indent=1)
    os.replace(path + ".tmp", path)
    print(path)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes a heavy mesh scene for editor measurements into OUT_DIR (never into the repo):
big_mesh.obj, a closed torus with a bumpy, scanned-like surface (positions and faces only,
about 1M triangles by default), and big_mesh.json, a 960x540 toon scene with outlines that
renders it on a ground quad.
usage: scripts/make_big_mesh.py OUT_DIR [--triangles 1000000]"""
import argparse
import json
import math
import os
import random


def torus(triangles, seed=1):
    """A (u, v) grid wrapped both ways: 2*nu*nv triangles, no seams, no holes."""
    nv = max(3, int(round(math.sqrt(triangles / 4))))
    nu = max(3, int(round(triangles / (2 * nv))))
    rng = random.Random(seed)
    # Broad lumps plus fine grain: a few waves at random phases, then per-vertex jitter.
    waves = [(rng.randint(1, 9), rng.randint(1, 7), rng.uniform(0, 2 * math.pi), 0.06 / (k + 1))
             for k in range(6)]
    big, small = 1.0, 0.42
    lines = []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        cu, su = math.cos(u), math.sin(u)
        for j in range(nv):
            v = 2 * math.pi * j / nv
            bump = sum(a * math.sin(fu * u + fv * v + p) for fu, fv, p, a in waves)
            r = small * (1 + bump + rng.gauss(0, 0.0008))
            ring = big + r * math.cos(v)
            lines.append(f"v {ring * cu:.5f} {r * math.sin(v) + small * 1.15:.5f} {ring * su:.5f}")
    for i in range(nu):
        i1 = (i + 1) % nu
        for j in range(nv):
            j1 = (j + 1) % nv
            a, b, c, d = i * nv + j + 1, i1 * nv + j + 1, i1 * nv + j1 + 1, i * nv + j1 + 1
            lines.append(f"f {a} {d} {c}")
            lines.append(f"f {a} {c} {b}")
    return lines, 2 * nu * nv


def scene():
    return {
        "format": "inkray-scene", "version": 1,
        "camera": {"look_from": [0.6, 2.4, 4.2], "look_at": [0, 0.45, 0], "up": [0, 1, 0], "vfov": 38},
        "render": {"width": 960, "height": 540, "spp": 64, "max_depth": 6},
        "environment": {"type": "gradient", "zenith": [0.25, 0.32, 0.5], "horizon": [0.7, 0.68, 0.64],
                        "nadir": [0.2, 0.18, 0.16]},
        "materials": [
            {"name": "clay", "type": "toon", "color": [0.78, 0.45, 0.28], "shadow_color": [0.35, 0.3, 0.45],
             "bands": 3},
            {"name": "ground", "type": "diffuse", "albedo": [0.45, 0.44, 0.42]}
        ],
        # The mesh comes first: the editor's --edit transform and material edit the first object.
        "objects": [
            {"name": "scan", "material": "clay", "shape": {"type": "mesh", "path": "big_mesh.obj"}},
            {"name": "ground", "material": "ground",
             "shape": {"type": "quad", "corner": [-6, 0, -6], "edge_u": [0, 0, 12], "edge_v": [12, 0, 0]}}
        ],
        "lights": [
            {"name": "sun", "type": "directional", "direction": [-0.5, -1, -0.4], "color": [1, 0.95, 0.86],
             "intensity": 2.5}
        ],
        "outlines": {"enabled": True, "width": 2}
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    parser.add_argument("--triangles", type=int, default=1000000)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    lines, count = torus(args.triangles)
    obj = os.path.join(args.out_dir, "big_mesh.obj")
    with open(obj, "w") as f:
        f.write(f"# inkray scripts/make_big_mesh.py: bumpy closed torus, {count} triangles\n")
        f.write("\n".join(lines))
        f.write("\n")
    doc = os.path.join(args.out_dir, "big_mesh.json")
    with open(doc, "w") as f:
        json.dump(scene(), f, indent=1)
        f.write("\n")
    print(f"{obj} ({count} triangles)\n{doc}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes legal but heavy scenes into a folder (default /tmp/inkray-stress), the large
inputs every phase must survive without hanging or exhausting memory: 550,000
objects, a closed white room at 1024 bounces, the anisotropic Kuwahara filter at
radius 64 on a 1080p image, and the same small scene at 1e-6 and 1e8 scale.
Nothing here is committed output; tests and docs/architecture.md say how each is
bounded. usage: scripts/make_stress_scenes.py [FOLDER]"""
import json
import os
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else "/tmp/inkray-stress"


def write(name, doc):
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name), "w") as f:
        json.dump(doc, f)
    print(os.path.join(OUT, name))


def base(camera=None, render=None):
    return {"format": "inkray-scene", "version": 1,
            "camera": camera or {"look_from": [0, 2, 8], "look_at": [0, 0.5, 0]},
            "render": render or {"width": 320, "height": 240, "spp": 16},
            "environment": {"type": "gradient"},
            "materials": [{"name": "clay", "type": "diffuse", "albedo": [0.8, 0.5, 0.3]}],
            "objects": [], "lights": [{"name": "sun", "type": "directional", "direction": [-1, -2, -1]}]}


def many_objects(n=550000):
    doc = base(camera={"look_from": [0, 300, 900], "look_at": [0, 0, 0]})
    side = int(n ** 0.5) + 1
    doc["objects"] = [{"name": f"o{i}", "material": "clay",
                       "shape": {"type": "sphere", "center": [i % side - side / 2, 0, i // side - side / 2],
                                 "radius": 0.4}} for i in range(n)]
    write("many_objects.json", doc)


def white_room():
    doc = base(camera={"look_from": [0, 0, 0], "look_at": [0, 0, -1]},
               render={"width": 320, "height": 240, "spp": 64, "max_depth": 1024})
    doc["materials"] = [{"name": "white", "type": "diffuse", "albedo": [1, 1, 1]},
                        {"name": "lamp", "type": "emissive", "color": [1, 1, 1], "strength": 1}]
    doc["objects"] = [{"name": "room", "material": "white", "shape": {"type": "sphere", "radius": 10}},
                      {"name": "bulb", "material": "lamp", "shape": {"type": "sphere", "center": [0, 5, -3],
                                                                      "radius": 0.5}}]
    doc["lights"] = []
    write("white_room_1024.json", doc)


def kuwahara_64():
    doc = base(render={"width": 1920, "height": 1080, "spp": 1, "painterly": "anisotropic",
                       "painterly_radius": 64})
    doc["objects"] = [{"name": "ball", "material": "clay", "shape": {"type": "sphere", "center": [0, 0.5, 0]}}]
    write("kuwahara_64.json", doc)


def scaled(name, s):
    doc = base(camera={"look_from": [0, 2 * s, 8 * s], "look_at": [0, 0.5 * s, 0]})
    doc["objects"] = [
        {"name": "ball", "material": "clay", "shape": {"type": "sphere", "center": [0, 0.5 * s, 0], "radius": 0.5 * s}},
        {"name": "ground", "material": "clay",
         "shape": {"type": "quad", "corner": [-5 * s, 0, 5 * s], "edge_u": [10 * s, 0, 0], "edge_v": [0, 0, -10 * s]}}]
    doc["outlines"] = {"enabled": True, "crease": {"enabled": True}, "unit": "pixels"}
    write(name, doc)


if __name__ == "__main__":
    many_objects()
    white_room()
    kuwahara_64()
    scaled("tiny_scale.json", 1e-6)
    scaled("huge_scale.json", 1e8)

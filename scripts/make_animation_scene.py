#!/usr/bin/env python3
"""Writes scenes/animation.json: 48 frames of a camera orbit, a bouncing toon ball with
outlines and a stroke-painted blob turning. The keys are computed here (an orbit and
parabolic bounces), so the scene is regenerated rather than edited by hand:
    scripts/make_animation_scene.py > scenes/animation.json
"""
import json
import math

FRAMES = 48
RADIUS, BALL = 9.0, 0.7


def keys(samples, interp="bezier"):
    return [{"frame": f, "value": v, "interp": interp} for f, v in samples]


def r(x):
    return round(x, 4)


# A quarter turn around the scene, keyed every 6 frames (bezier between keys holds the circle).
orbit = []
for f in range(1, FRAMES + 2, 6):
    a = math.radians(-30 + 90 * (f - 1) / FRAMES)
    orbit.append((f, [r(RADIUS * math.sin(a)), 3.2, r(RADIUS * math.cos(a))]))

# Three bounces of 16 frames: a parabola sampled every 2 frames, a squash at each contact.
bounce, squash = [], []
for f in range(1, FRAMES + 2, 2):
    t = ((f - 1) % 16) / 16.0
    bounce.append((f, [-1.8, r(BALL + 1.5 * 4 * t * (1 - t)), 1.0]))
for start in range(1, FRAMES + 2, 16):
    squash += [(start - 1, [1, 1, 1]), (start, [1.18, 0.8, 1.18]), (start + 1, [1, 1, 1])]
squash = [k for k in squash if 1 <= k[0] <= FRAMES + 1]
if squash[0][0] != 1:
    squash.insert(0, (1, [1, 1, 1]))

scene = {
    "format": "inkray-scene",
    "version": 1,
    "camera": {"look_from": orbit[0][1], "look_at": [0, 0.9, 0], "up": [0, 1, 0], "vfov": 30},
    "render": {"width": 960, "height": 540, "spp": 32, "max_depth": 8, "clamp": 3,
               "frame_start": 1, "frame_end": FRAMES, "fps": 24, "frame": 1,
               "shutter_open": -0.25, "shutter_close": 0.25},
    "environment": {"type": "gradient", "zenith": [0.16, 0.24, 0.46], "horizon": [0.5, 0.5, 0.54],
                    "nadir": [0.1, 0.09, 0.08]},
    "outlines": {"enabled": True, "width": 2.5,
                 "silhouette": {"enabled": True, "color": [0.08, 0.05, 0.12]},
                 "object": {"enabled": True, "color": [0.08, 0.05, 0.12]}},
    "materials": [
        {"name": "ground", "type": "toon", "environment": 1, "color": [0.78, 0.74, 0.62],
         "shadow_color": [0.45, 0.5, 0.7], "threshold": 0.3, "softness": 0.03, "specular": False},
        {"name": "ball", "type": "toon", "environment": 1, "color": [0.92, 0.36, 0.24],
         "shadow_color": [0.35, 0.3, 0.5], "bands": 3, "threshold": 0.35, "softness": 0.02,
         "specular_size": 0.12, "shininess": 60, "rim": True, "rim_color": [0.45, 0.45, 0.55], "rim_threshold": 0.75},
        {"name": "ochre", "type": "diffuse", "albedo": [0.85, 0.52, 0.12]},
        {"name": "teal", "type": "diffuse", "albedo": [0.1, 0.45, 0.5]},
        {"name": "paint", "type": "mix", "a": "ochre", "b": "teal", "factor": 0.4},
    ],
    "objects": [
        {"name": "ground", "material": "ground",
         "shape": {"type": "quad", "corner": [-40, 0, -40], "edge_u": [0, 0, 80], "edge_v": [80, 0, 0]}},
        {"name": "ball", "material": "ball", "shape": {"type": "sphere", "radius": BALL},
         "transform": {"translate": bounce[0][1]}},
        {"name": "blob", "material": "paint", "shape": {"type": "mesh", "path": "meshes/bumpy_blob.obj"},
         "transform": {"scale": [1.1, 1.1, 1.1], "rotate": [{"axis": [0, 1, 0], "degrees": 0}],
                       "translate": [1.6, 1.2, -0.4]}},
    ],
    "strokes": [
        {"name": "blob_strokes", "object": "blob", "seed": 11, "count": 900,
         "width_min": 0.08, "width_max": 0.14, "length_min": 0.3, "length_max": 0.5,
         "flow": [0.3, 1, 0.1], "rotation_jitter": 20, "hue_jitter": 10, "saturation_jitter": 0.12,
         "value_jitter": 0.15, "brush": "bristle", "bristles": 12, "pressure": 0.6, "segments": 8}
    ],
    "lights": [
        {"name": "sun", "type": "directional", "direction": [-0.6, -1, -0.45], "color": [1.0, 0.96, 0.88],
         "intensity": 3.5},
        {"name": "fill", "type": "point", "position": [-5, 3, 5], "color": [0.8, 0.85, 1.0], "intensity": 14},
    ],
    "animation": [
        {"target": "camera/look_from", "keys": keys(orbit)},
        {"target": "objects/ball/transform/translate", "keys": keys(bounce, "linear")},
        {"target": "objects/ball/transform/scale", "keys": keys(squash, "linear")},
        {"target": "objects/blob/transform/rotate/0/degrees",
         "keys": keys([(1, 0), (FRAMES + 1, 180)], "linear")},
    ],
}


def compact(value, indent=0):
    """JSON with short arrays and key objects on one line, like the other example scenes."""
    pad = "  " * indent
    if isinstance(value, dict):
        flat = json.dumps(value)
        if len(flat) <= 130 or "frame" in value:
            return flat
        items = [f'{pad}  {json.dumps(k)}: {compact(v, indent + 1)}' for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list):
        flat = json.dumps(value)
        if len(flat) <= 100:
            return flat
        items = [f"{pad}  {compact(v, indent + 1)}" for v in value]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(value)


print(compact(scene))

#!/usr/bin/env python3
"""Generates the image brushes under resources/brushes/: white RGBA PNGs whose
alpha is the paint a stroke leaves, the stroke running left to right along x
(where the brush lands to where it lifts) and across y. Pure Python and a fixed
integer hash (no random module), so the outputs are identical on every machine;
they are committed."""
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "brushes")


def png_rgba(path, width, height, alpha):
    """Writes white pixels with alpha(x, y) in [0, 1] as an 8-bit RGBA PNG."""
    rows = []
    for y in range(height):
        row = bytearray(b"\x00")  # filter type: none
        for x in range(width):
            a = int(round(min(max(alpha(x, y), 0.0), 1.0) * 255.0))
            row += bytes((255, 255, 255, a))
        rows.append(bytes(row))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(b"".join(rows), 9)))
        f.write(chunk(b"IEND", b""))


def hash_unit(*values):
    """A uniform number in [0, 1) from integers (a 32-bit integer hash)."""
    h = 0x811C9DC5
    for v in values:
        h ^= v & 0xFFFFFFFF
        h = (h * 0x01000193) & 0xFFFFFFFF
        h ^= h >> 15
        h = (h * 0x2C1B3C6D) & 0xFFFFFFFF
        h ^= h >> 12
        h = (h * 0x297A2D39) & 0xFFFFFFFF
        h ^= h >> 15
    return h / 4294967296.0


def noise1(x, seed):
    """Smooth 1D value noise in [0, 1]."""
    i = math.floor(x)
    t = x - i
    t = t * t * (3.0 - 2.0 * t)
    return hash_unit(seed, i) * (1.0 - t) + hash_unit(seed, i + 1) * t


def smoothstep(e0, e1, x):
    t = min(max((x - e0) / (e1 - e0), 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def dab(x, y, w, h):
    """A loaded round brush: a short oval of paint with soft ends, a thick
    rim where the paint was pushed aside, and faint bristle ridges."""
    s = x / (w - 1)  # along, 0 to 1
    t = 2.0 * y / (h - 1) - 1.0  # across, -1 to 1
    # Oval outline, fuller at the landing end, wavy at the sides.
    half = 0.95 * max(0.0, 1.0 - ((s - 0.47) / 0.47) ** 2) ** 0.3
    half *= 0.9 + 0.1 * noise1(s * 6.0, 11)
    edge = smoothstep(half, half - 0.18, abs(t))
    rim = 1.0 + 0.25 * smoothstep(half - 0.35, half - 0.12, abs(t))
    ridges = 0.85 + 0.15 * noise1(t * 13.0 + 40.0, 12) * noise1(s * 3.0 + 5.0 * t, 13)
    return edge * min(1.0, 0.85 * rim * ridges)


def dry_bristle(x, y, w, h):
    """A dry brush dragged along: separate bristle streaks that each run out
    of paint at their own length and break up into grain."""
    s = x / (w - 1)
    t = 2.0 * y / (h - 1) - 1.0
    bristles = 22.0
    f = (t + 1.0) * 0.5 * bristles
    b = math.floor(f)
    load = 0.5 + 0.5 * hash_unit(21, b)
    reach = 0.45 + 0.55 * hash_unit(22, b)
    streak_pos = f - b
    thickness = 0.25 + 0.3 * hash_unit(23, b)
    streak = smoothstep(0.5, 0.5 - thickness, abs(streak_pos - 0.5))
    head = smoothstep(0.0, 0.05 + 0.05 * hash_unit(24, b), s)
    tail = smoothstep(reach, reach - 0.25, s)
    grain = smoothstep(0.3, 0.6, 0.5 * (noise1(s * 40.0 + 17.0 * b, 25) + noise1(s * 97.0 + 5.0 * b, 26))
                       + 0.5 * (1.0 - s))
    sides = smoothstep(1.0, 0.85, abs(t))
    return sides * head * tail * (0.25 + 0.75 * streak) * load * grain * 1.3


def palette_knife(x, y, w, h):
    """Paint laid with a knife: a flat, nearly opaque slab with a straight
    landing edge, a torn trailing edge, and thin scrapes along the stroke."""
    s = x / (w - 1)
    t = 2.0 * y / (h - 1) - 1.0
    sides = smoothstep(0.97, 0.9, abs(t) + 0.04 * noise1(s * 9.0, 31))
    head = smoothstep(0.0, 0.02, s - 0.03 * t * t)
    torn = 0.84 + 0.1 * noise1(t * 7.0, 32) + 0.05 * noise1(t * 31.0, 33)
    tail = smoothstep(torn, torn - 0.05, s)
    scrape = noise1(t * 45.0, 34)
    scrapes = 1.0 - 0.7 * smoothstep(0.82, 0.95, scrape) * smoothstep(0.2, 0.5, s)
    thin = 1.0 - 0.25 * smoothstep(0.4, 1.0, s) * noise1(t * 5.0 + s * 3.0, 35)
    return sides * head * tail * scrapes * thin


BRUSHES = {
    "dab.png": (dab, 256, 96),
    "dry_bristle.png": (dry_bristle, 512, 128),
    "palette_knife.png": (palette_knife, 256, 96),
}

if __name__ == "__main__":
    os.makedirs(ROOT, exist_ok=True)
    for name, (shape, width, height) in BRUSHES.items():
        png_rgba(os.path.join(ROOT, name), width, height, lambda x, y: shape(x, y, width, height))

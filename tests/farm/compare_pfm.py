#!/usr/bin/env python3
"""Compares two PFM images pixel by pixel: exit 0 when every channel of A is within
ABS + REL * |B| of B's, else 1 with the worst pixel. usage: compare_pfm.py A B ABS REL"""

import struct
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # "PF" or "Pf", width, height, scale, each ended by whitespace
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end].decode("ascii"))
        pos = end
    pos += 1  # the one whitespace byte before the pixels
    kind, width, height, scale = fields[0], int(fields[1]), int(fields[2]), float(fields[3])
    channels = {"PF": 3, "Pf": 1}[kind]
    count = width * height * channels
    values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", data[pos:pos + 4 * count])
    return width, height, channels, values


def main(a_path, b_path, abs_tol, rel_tol):
    wa, ha, ca, a = read_pfm(a_path)
    wb, hb, cb, b = read_pfm(b_path)
    if (wa, ha, ca) != (wb, hb, cb):
        print(f"size differs: {wa}x{ha}x{ca} against {wb}x{hb}x{cb}")
        return 1
    worst, worst_i, differing = 0.0, 0, 0
    for i, (x, y) in enumerate(zip(a, b)):
        excess = abs(x - y) - (float(abs_tol) + float(rel_tol) * abs(y))
        differing += x != y
        if excess > worst:
            worst, worst_i = excess, i
    print(f"{differing} of {len(a)} values differ; largest difference "
          f"{max((abs(x - y) for x, y in zip(a, b)), default=0):.3g}")
    if worst > 0:
        pixel = worst_i // ca
        print(f"out of tolerance at pixel ({pixel % wa}, {ha - 1 - pixel // wa}): "
              f"{a[worst_i]} against {b[worst_i]}")
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 5:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))

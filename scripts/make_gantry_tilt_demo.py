#!/usr/bin/python3
"""Writes the gantry-tilt picture's three NRRD files into a folder: a cylinder standing along z
with a ball at its middle, scanned with a 25-degree tilt (tilted.nrrd), the same slices with the
tilt left out of the header as the nearest rotation draws them (before.nrrd), and scanned upright
(upright.nrrd)."""
import math
import os
import sys

import numpy as np

NX, NY, NZ, GROW = 128, 128, 60, 56  # the upright scan has the rows the tilt spreads over
STEP = 2 * math.tan(math.radians(25))  # rows a slice moves along y, every 2 along z


def phantom(x, y, z):
    cylinder = np.clip(20.5 - np.hypot(x - 64, y - 90), 0, 1) * 200
    ball = np.clip(30.5 - np.sqrt((x - 64) ** 2 + (y - 90) ** 2 + (z - 60) ** 2), 0, 1) * 120
    return np.maximum(cylinder, ball).astype(np.uint8)


def write(path, values, third):
    nz, ny, nx = values.shape
    header = (f"NRRD0004\ntype: uint8\ndimension: 3\nspace: left-posterior-superior\n"
              f"sizes: {nx} {ny} {nz}\nspace directions: (1,0,0) (0,1,0) {third}\n"
              f"space origin: (0,0,0)\nencoding: raw\nendian: little\n\n")
    with open(path, "wb") as f:
        f.write(header.encode() + values.tobytes())


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    k, j, i = np.mgrid[0:NZ, 0:NY, 0:NX].astype(np.float32)
    tilted = phantom(i, j + STEP * k, 2 * k)  # slice k sampled STEP * k rows further along y
    write(os.path.join(out, "tilted.nrrd"), tilted, f"(0,{STEP},2)")
    write(os.path.join(out, "before.nrrd"), tilted, f"(0,0,{math.hypot(STEP, 2)})")
    k, j, i = np.mgrid[0:NZ, 0:NY + GROW, 0:NX].astype(np.float32)
    write(os.path.join(out, "upright.nrrd"), phantom(i, j, 2 * k), "(0,0,2)")


if __name__ == "__main__":
    main()

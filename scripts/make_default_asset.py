#!/usr/bin/env python3
"""Writes assets/default.nrrd: the viewer's default volume, a synthetic 96^3 uint8 field.

It is the electron density of a hydrogen 3d_z2 orbital plus a faint 2s-like shell, sampled on
a 96^3 grid with spacing 1 and stored as gzip-encoded NRRD. Made by code so the project ships
no third-party data; run it again to regenerate the file byte for byte.
"""
import gzip
import math
import os

N = 96
out = os.path.join(os.path.dirname(__file__), "..", "assets", "default.nrrd")
data = bytearray(N * N * N)
c = (N - 1) / 2.0
scale = 13.0 / c  # Bohr radii per voxel
tilt = math.radians(25.0)  # the ring tilts towards a +z viewer, so it reads as a ring
peak = 0.0
vals = []
for k in range(N):
    for j in range(N):
        for i in range(N):
            x, y, z = (i - c) * scale, (j - c) * scale, (k - c) * scale
            r = math.sqrt(x * x + y * y + z * z)
            axis = y * math.cos(tilt) - z * math.sin(tilt)  # lobes along y, tilted about x
            cos_t = axis / r if r > 0 else 0.0
            d = r ** 4 * math.exp(-2.0 * r / 3.0) * (3 * cos_t * cos_t - 1) ** 2
            s = 0.02 * (r ** 2) * math.exp(-r / 2.0) * (1 - r / 8.0) ** 2 * 40
            vals.append(d + s)
peak = max(vals)
for n, v in enumerate(vals):
    data[n] = min(255, int(255.0 * math.sqrt(v / peak) + 0.5))
header = (
    "NRRD0004\n"
    "# ewaview default volume: hydrogen 3d orbital density, lobes along y (scripts/make_default_asset.py)\n"
    "type: uint8\n"
    "dimension: 3\n"
    f"sizes: {N} {N} {N}\n"
    "spacings: 1 1 1\n"
    "encoding: gzip\n"
    "\n"
)
with open(out, "wb") as f:
    f.write(header.encode("ascii"))
    f.write(gzip.compress(bytes(data), compresslevel=9, mtime=0))
print(out, os.path.getsize(out), "bytes")

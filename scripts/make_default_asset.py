#!/usr/bin/env python3
"""Writes assets/default.nrrd: the viewer's default volume, a synthetic gearbox, uint8.

Two meshing spur gears (14 and 9 teeth, the big one with five lightening holes and a raised
hub) on shafts through an open casing (its lid off, so the gears are in view), built from
signed distance functions with edges smoothed over about a voxel, so the splats show clean
surfaces rather than staircases. The assembly is tilted towards a viewer on +z (VTK's default
view) so that the first picture shows the gears' faces, their thickness and the shafts, and the
grid is cropped to the object so that the default camera fills the window with it. Values
(which assets/default.tf.json colours): casing 70, bearing bosses 110, shafts 140, small gear
200, big gear 230. Made by code so the project ships no third-party data; run it again to
regenerate the file byte for byte (pure Python, about 15 s).
"""
import gzip
import math
import os

SCALE = 0.95  # voxels per unit of the design below
TILT_X, TILT_Y = math.radians(-50.0), math.radians(15.0)  # the faces turned towards +z
EDGE = 0.7  # half-width of the smoothed edge, voxels

cx, sx = math.cos(TILT_X), math.sin(TILT_X)
cy, sy = math.cos(TILT_Y), math.sin(TILT_Y)


def to_world(u, v, w):
    """The design's axes (gear axes along w) tilted: Ry(TILT_Y) Rx(TILT_X)."""
    y1, z1 = cx * v - sx * w, sx * v + cx * w
    return cy * u + sy * z1, y1, -sy * u + cy * z1


def to_design(x, y, z):
    x1, z1 = cy * x - sy * z, sy * x + cy * z
    return x1, cx * y + sx * z1, -sx * y + cx * z1


def cover(d):
    """Signed distance (negative inside) to a smooth 0..1 occupancy."""
    t = 0.5 - d / (2.0 * EDGE)
    return 0.0 if t <= 0.0 else (1.0 if t >= 1.0 else t * t * (3.0 - 2.0 * t))


def gear(du, dv, w, teeth, pitch, module, half, bore, holes, phase):
    """Spur gear about the w axis: trapezoid teeth, a bore, lightening holes, a raised hub."""
    rho = math.hypot(du, dv)
    tip, root = pitch + module, pitch - 1.2 * module
    if rho > tip + 2.0:
        return rho - tip
    f = ((math.atan2(dv, du) - phase) * teeth / (2.0 * math.pi)) % 1.0
    e = abs(f - 0.5) * 2.0  # 0 at a tooth's centre, 1 between teeth
    h = 1.0 if e < 0.35 else (0.0 if e > 0.75 else (0.75 - e) / 0.4)
    d = max(rho - (root + (tip - root) * h), bore - rho)
    for k in range(holes):
        a = phase + 2.0 * math.pi * (k + 0.5) / holes
        r = 0.64 * root
        d = max(d, 0.2 * root - math.hypot(du - r * math.cos(a), dv - r * math.sin(a)))
    thick = half if rho > 0.42 * root else 1.7 * half
    return max(d, abs(w) - thick)


def casing(u, v, w, r1, r2, length, half, round_):
    """The hull of two circles (r1 at u = 0, r2 at u = length) extruded to |w| <= half, its
    edges rounded by round_."""
    px, py = abs(v), u
    b = (r1 - r2) / length
    a = math.sqrt(1.0 - b * b)
    k = -b * px + a * py
    if k < 0.0:
        d2 = math.hypot(px, py) - r1
    elif k > a * length:
        d2 = math.hypot(px, py - length) - r2
    else:
        d2 = a * px + b * py - r1
    qx, qz = d2 + round_, abs(w) - half + round_
    return math.hypot(max(qx, 0.0), max(qz, 0.0)) + min(max(qx, qz), 0.0) - round_


MODULE = 3.0 * SCALE
PITCH_A, PITCH_B = 7.0 * MODULE, 4.5 * MODULE  # 14 and 9 teeth
GEAR_A = (-(PITCH_A + PITCH_B) / 2.0, 0.0)
GEAR_B = (GEAR_A[0] + PITCH_A + PITCH_B, 0.0)
MARGIN = 3.0 * SCALE
SHAFT_HALF = 17.0 * SCALE
WALL_HALF = 9.0 * SCALE


def value(u, v, w):
    dc = casing(u - GEAR_A[0], v, w, PITCH_A + MODULE + MARGIN, PITCH_B + MODULE + MARGIN,
                GEAR_B[0] - GEAR_A[0], WALL_HALF, 4.0 * SCALE)
    if dc >= 2.0:
        return 0.0
    shell = abs(dc + 1.1 * SCALE) - 1.1 * SCALE  # a wall 2.2 units thick
    shell = max(shell, w - 6.0 * SCALE)  # the lid off: the gears in view
    val = 70.0 * cover(shell)
    for (gu, gv), radius in ((GEAR_A, 3.0 * SCALE), (GEAR_B, 2.4 * SCALE)):
        axis = math.hypot(u - gu, v - gv)
        val = max(val, 140.0 * cover(max(axis - radius, abs(w) - SHAFT_HALF)))
        boss = max(axis - 2.0 * radius, abs(abs(w) - WALL_HALF) - 2.0 * SCALE)
        val = max(val, 110.0 * cover(boss))
    da = gear(u - GEAR_A[0], v - GEAR_A[1], w, 14, PITCH_A, MODULE, 3.2 * SCALE, 3.0 * SCALE, 5,
              0.0)
    val = max(val, 230.0 * cover(da))
    db = gear(u - GEAR_B[0], v - GEAR_B[1], w, 9, PITCH_B, MODULE, 3.2 * SCALE, 2.4 * SCALE, 0,
              math.pi / 9.0)  # half a tooth turned: the teeth mesh
    return max(val, 200.0 * cover(db))


def main():
    # A grid round the tilted casing and shafts, then cropped to the voxels that are not zero.
    u_lo = GEAR_A[0] - PITCH_A - MODULE - MARGIN
    u_hi = GEAR_B[0] + PITCH_B + MODULE + MARGIN
    v_hi = PITCH_A + MODULE + MARGIN
    corners = [to_world(u, v, w) for u in (u_lo, u_hi) for v in (-v_hi, v_hi)
               for w in (-SHAFT_HALF, SHAFT_HALF)]
    lo = [min(p[a] for p in corners) - 2.0 for a in range(3)]
    hi = [max(p[a] for p in corners) + 2.0 for a in range(3)]
    dims = [int(math.ceil(hi[a] - lo[a])) + 1 for a in range(3)]
    centre = [(hi[a] + lo[a]) / 2.0 - (dims[a] - 1) / 2.0 for a in range(3)]
    nx, ny, nz = dims
    data = bytearray(nx * ny * nz)
    first, last = [nx, ny, nz], [-1, -1, -1]
    n = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                u, v, w = to_design(i + centre[0], j + centre[1], k + centre[2])
                data[n] = int(value(u, v, w) + 0.5)
                if data[n]:
                    first = [min(first[0], i), min(first[1], j), min(first[2], k)]
                    last = [max(last[0], i), max(last[1], j), max(last[2], k)]
                n += 1
    first = [max(0, f - 1) for f in first]
    last = [min(dims[a] - 1, last[a] + 1) for a in range(3)]
    sizes = [last[a] - first[a] + 1 for a in range(3)]
    cropped = bytearray()
    for k in range(first[2], last[2] + 1):
        for j in range(first[1], last[1] + 1):
            row = (k * ny + j) * nx
            cropped += data[row + first[0]:row + last[0] + 1]
    out = os.path.join(os.path.dirname(__file__), "..", "assets", "default.nrrd")
    header = (
        "NRRD0004\n"
        "# ewaview default volume: two meshing gears in an open casing (scripts/make_default_asset.py)\n"
        "type: uint8\n"
        "dimension: 3\n"
        f"sizes: {sizes[0]} {sizes[1]} {sizes[2]}\n"
        "spacings: 1 1 1\n"
        "encoding: gzip\n"
        "\n"
    )
    with open(out, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(gzip.compress(bytes(cropped), compresslevel=9, mtime=0))
    print(out, sizes, os.path.getsize(out), "bytes")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The CPU splatter against the rasterized path on every shared volume's default view.

Renders each volume of ../shared/data at 512x512 with --splatter raster and --splatter cpu
(the same build), and prints per volume the SSIM (8x8 windows, stride 4, RGB) and the largest
channel difference, as CSV. Needs numpy and PIL (Debian's python3-numpy, python3-pil).
Usage: scripts/cpu_splatter_agreement.py [BUILD/ewaview] [DATA] [OUTDIR] [OPTION...]
(OPTIONs go to both pictures' command lines, e.g. --shading --post-normals field).
"""
import os
import subprocess
import sys

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from PIL import Image

VOLUMES = ["engine/engine.nhdr", "bonsai/bonsai.nhdr", "aneurism/aneurism.nhdr",
           "cthead/CThead.nhdr", "tooth/tooth.nrrd", "lidc2/LIDC2.mha",
           "headmr/HeadMRVolume.mhd", "hydrogen/hydrogenatom.dat", "nucleon/nucleon.nrrd",
           "walnut/walnut.dat", "fetal-t2/template_T2.nrrd", "neghip/neghip.slc",
           "headsq/quarter.nhdr", "dicom-pet", "nifti/anatomical.nii"]


def ssim(a, b):
    """Mean SSIM over 8x8 windows (stride 4) and the three channels."""
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    values = []
    for c in range(3):
        x = sliding_window_view(a[:, :, c].astype(np.float64), (8, 8))[::4, ::4]
        y = sliding_window_view(b[:, :, c].astype(np.float64), (8, 8))[::4, ::4]
        mx, my = x.mean((-1, -2)), y.mean((-1, -2))
        vx, vy = x.var((-1, -2)), y.var((-1, -2))
        cov = ((x - mx[..., None, None]) * (y - my[..., None, None])).mean((-1, -2))
        s = ((2 * mx * my + c1) * (2 * cov + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2))
        values.append(s.mean())
    return float(np.mean(values))


def main():
    ewaview = sys.argv[1] if len(sys.argv) > 1 else "build/ewaview"
    data = sys.argv[2] if len(sys.argv) > 2 else "../shared/data"
    out = sys.argv[3] if len(sys.argv) > 3 else "/tmp/cpu_splatter_agreement"
    options = sys.argv[4:]
    os.makedirs(out, exist_ok=True)
    print("volume,ssim,max_levels")
    for volume in VOLUMES:
        path = os.path.join(data, volume)
        if not os.path.exists(path):
            continue
        pictures = []
        for splatter in ("raster", "cpu"):
            png = os.path.join(out, volume.replace("/", "_") + "_" + splatter + ".png")
            subprocess.run(["xvfb-run", "-a", ewaview, path, "--splatter", splatter,
                            "--resolution", "512,512", "--output", png] + options, check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            pictures.append(np.asarray(Image.open(png).convert("RGB")))
        a, b = pictures
        worst = int(np.abs(a.astype(int) - b.astype(int)).max())
        print(f"{volume.split('/')[0]},{ssim(a, b):.5f},{worst}", flush=True)


if __name__ == "__main__":
    main()

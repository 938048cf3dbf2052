#!/usr/bin/python3
"""Close-ups of shared volumes: ewaview's splatting (each classification and kernel width) beside
VTK's CPU ray caster with the same data, transfer function and camera.

For each volume and each (classification, kernel width) it prints SSIM on luminance against
VTK's picture, the sharpness ratio (mean luminance gradient over the pixels where VTK's picture
has edges, ours over VTK's) and milliseconds per frame (median wall time of render() after a
first, classifying frame), as one Markdown table; with --out it writes the pictures and a
montage per volume (VTK, then the variants in the order of the table). With --views, one row
per volume and variant: SSIM / sharpness at each view, marked * where the view is flat (VTK's
picture has no luminance step above FLAT_GRADIENT a pixel: a smooth field, or a surface filling
the picture whose "edges" are the ray caster's sampling steps), and the worst sharpness over
all views and over the views with edges.

  PYTHONPATH=build/python /usr/bin/python3 scripts/crisp_compare.py --out crisp_out

The reference is VTK's own ray-cast image (--vtk-picture rays): VTK 9.1 shows that image in its
window stretched by U / (U - 1) about its centre (U its width in pixels: 384/383 for a close-up),
a half-texel offset of its display helper's texture coordinates, which moves edges by up to half
a pixel and resamples the picture; --vtk-picture window compares with the window as shown.

Needs the ewaview module (build/python), NumPy and python3-vtk9 (VTK renders off screen; run
under xvfb-run without a display).
"""
import argparse
import os
import statistics
import sys
import time

import subprocess
import tempfile

import numpy as np

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "data")
if not os.path.isdir(DATA):  # a git worktree beside the main checkout
    DATA = "/work/shared/data"
SIZE = 384


def raw(path, dtype, shape, offset=0):
    with open(path, "rb") as f:
        f.seek(offset)
        a = np.frombuffer(f.read(), dtype=dtype, count=int(np.prod(shape)))
    return a.reshape(shape).astype(dtype.lstrip("<>=") if dtype[0] in "<>" else dtype)


def after_header(path, marker):
    """The bytes of a file after its text header (which ends with `marker`)."""
    with open(path, "rb") as f:
        data = f.read()
    return data[data.index(marker) + len(marker):]


def lidc2():
    import zlib
    body = after_header(os.path.join(DATA, "lidc2", "LIDC2.mha"), b"ElementDataFile = LOCAL\n")
    return np.frombuffer(zlib.decompress(body), "u1").reshape(133, 256, 256)


def loaded(path):
    """A file's voxels as ewaview reads them (formats numpy alone does not: SLC, DICOM), given to
    both renderers as an array."""
    import ewaview
    return ewaview.Scene(os.path.join(DATA, path)).array


def fetal_t2():
    import gzip
    body = after_header(os.path.join(DATA, "fetal-t2", "template_T2.nrrd"), b"\n\n")
    return np.frombuffer(gzip.decompress(body), "<f4").reshape(126, 159, 117).astype(np.float32)


def headsq():
    return np.stack([raw(os.path.join(DATA, "headsq", f"quarter.{k}"), "<i2", (64, 64))
                     for k in range(1, 94)])


def tooth():
    path = os.path.join(DATA, "tooth", "tooth.nrrd")
    with open(path, "rb") as f:
        head = f.read(4096)
    return raw(path, "u1", (161, 94, 103), head.index(b"\n\n") + 2)


# name: (array [z, y, x], spacing (x, y, z), transfer function, eye direction, distance)
# Distances give 2 to 3 pixels a voxel at the focal point (30 degrees, 384 pixels).
def volumes():
    d = DATA
    return {
        "aneurism": lambda: (raw(f"{d}/aneurism/aneurism.raw", "u1", (256, 256, 256)), (1, 1, 1),
                     {"opacity": [[0, 0], [40, 0], [90, 0.5], [255, 0.9]],
                      "color": [[0, 0.8, 0.2, 0.1], [120, 1, 0.6, 0.4], [255, 1, 1, 0.9]]},
                     (0.6, -1.0, 0.5), 250.0),
        "bonsai": lambda: (raw(f"{d}/bonsai/bonsai.raw", "u1", (256, 256, 256)), (1, 1, 1),
                   {"opacity": [[0, 0], [55, 0], [65, 0.15], [90, 0.3], [255, 0.9]],
                    "color": [[0, 0.3, 0.6, 0.2], [45, 0.35, 0.65, 0.25], [90, 0.6, 0.45, 0.25],
                              [150, 0.85, 0.75, 0.6], [255, 1, 1, 1]]},
                   (1.0, -0.8, 0.4), 260.0),
        "engine": lambda: (raw(f"{d}/engine/engine.raw", "u1", (128, 256, 256)), (1, 1, 1),
                   {"opacity": [[0, 0], [120, 0], [140, 0.04], [160, 0.04], [175, 0],
                                [185, 0], [200, 0.7], [255, 0.9]],
                    "color": [[0, 0.5, 0.6, 0.9], [160, 0.6, 0.7, 1.0], [190, 1, 0.7, 0.3],
                              [255, 1, 1, 0.9]]},
                   (0.8, -1.0, 0.9), 250.0),
        "CThead": lambda: (raw(f"{d}/cthead/CThead.raw", ">u2", (113, 256, 256)), (1, 1, 2),
                   {"opacity": [[0, 0], [1100, 0], [1400, 0.6], [3272, 0.9]],
                    "color": [[0, 0.9, 0.7, 0.6], [1400, 1, 0.95, 0.85], [3272, 1, 1, 1]]},
                   (1.0, -0.5, 0.3), 280.0),
        "tooth": lambda: (tooth(), (1, 1, 1),
                  {"opacity": [[0, 0], [90, 0], [110, 0.25], [150, 0.25], [190, 0.9],
                               [255, 0.9]],
                   "color": [[0, 0.9, 0.8, 0.6], [150, 0.95, 0.85, 0.7], [200, 1, 1, 1],
                             [255, 1, 1, 1]]},
                  (1.0, 0.6, 0.4), 230.0),
        # Not in the default list (measured later): a uint16 MR volume whose transfer function
        # rises within a narrow part of its wide value range (1026 to 5119).
        "mrbrain": lambda: (raw(f"{d}/mrbrain/MRbrain.raw", ">u2", (109, 256, 256)), (1, 1, 2),
                    {"opacity": [[0, 0], [1075, 0], [1137, 0.3], [1932, 0.8], [2989, 0.9]],
                     "color": [[0, 0.8, 0.4, 0.3], [1137, 1, 0.8, 0.6], [2989, 1, 1, 1]]},
                    (0.9, -1.0, 0.6), 240.0),
        # Nor these four, chosen later as views no setting was tuned on: a walnut CT (uint16),
        # a chest CT with anisotropic spacing (1.41, 1.41, 2.5), a float32 fetal MR atlas, and
        # the hydrogen orbital's smooth density.
        "walnut": lambda: (raw(f"{d}/walnut/walnut.raw", "<u2", (114, 96, 128)), (1, 1, 1),
                   {"opacity": [[0, 0], [5000, 0], [7000, 0.3], [10000, 0.8], [22526, 0.9]],
                    "color": [[0, 0.6, 0.45, 0.3], [7000, 0.8, 0.65, 0.45],
                              [10000, 1, 0.9, 0.75], [22526, 1, 1, 1]]},
                   (1.0, -0.7, 0.5), 250.0),
        "lidc2": lambda: (lidc2(), (1.40625, 1.40625, 2.5),
                  {"opacity": [[0, 0], [100, 0], [140, 0.4], [255, 0.9]],
                   "color": [[0, 0.9, 0.6, 0.5], [140, 1, 0.85, 0.75], [255, 1, 1, 1]]},
                  (0.3, -1.0, 0.4), 330.0),
        "fetal-t2": lambda: (fetal_t2(), (0.859375,) * 3,
                     {"opacity": [[0, 0], [350, 0], [450, 0.3], [600, 0.8], [711, 0.9]],
                      "color": [[0, 0.7, 0.5, 0.4], [450, 0.95, 0.8, 0.6], [711, 1, 1, 1]]},
                     (1.0, -0.6, 0.5), 190.0),
        "hydrogen": lambda: (raw(f"{d}/hydrogen/hydrogenatom.raw", "u1", (128, 128, 128)),
                     (1, 1, 1),
                     {"opacity": [[0, 0], [10, 0], [30, 0.1], [80, 0.5], [255, 0.9]],
                      "color": [[0, 0.2, 0.5, 1], [30, 0.4, 0.7, 1], [80, 1, 0.8, 0.3],
                                [255, 1, 1, 0.9]]},
                     (1.0, -0.8, 0.6), 250.0),
        # And three small or coarse ones: a quarter-resolution CT head (spacing 3.2, 3.2, 1.5),
        # an MR head of 4-unit voxels, and the 41^3 nucleon.
        "headsq": lambda: (headsq(), (3.2, 3.2, 1.5),
                   {"opacity": [[0, 0], [1500, 0], [1800, 0.6], [3926, 0.9]],
                    "color": [[0, 0.9, 0.75, 0.6], [1800, 1, 0.95, 0.85], [3926, 1, 1, 1]]},
                   (0.4, -1.0, 0.3), 300.0),
        "headmr": lambda: (raw(f"{d}/headmr/HeadMRVolume.raw", "u1", (42, 62, 48)), (4, 4, 4),
                   {"opacity": [[0, 0], [60, 0], [90, 0.4], [255, 0.9]],
                    "color": [[0, 0.9, 0.6, 0.5], [90, 1, 0.85, 0.7], [255, 1, 1, 1]]},
                   (1.0, -0.5, 0.4), 450.0),
        "nucleon": lambda: (raw(f"{d}/nucleon/nucleon.raw", "u1", (41, 41, 41)), (1, 1, 1),
                    {"opacity": [[0, 0], [60, 0], [80, 0.15], [110, 0], [180, 0], [200, 0.8],
                                 [255, 0.9]],
                     "color": [[0, 0.3, 0.5, 1], [80, 0.4, 0.6, 1], [200, 1, 0.7, 0.3],
                               [255, 1, 1, 0.9]]},
                    (1.0, -0.7, 0.5), 100.0),
        # And two read by ewaview's own loaders (ewaview.Scene(...).array), chosen 2026-11-28,
        # nothing tuned on them: the 66^3 negative-potential field (SLC) and a whole-body PET
        # series (299 DICOM files, float after each slice's rescale; the body's uptake about
        # 2500, the hot organs above 10000).
        "neghip": lambda: (loaded("neghip/neghip.slc"), (1, 1, 1),
                   {"opacity": [[0, 0], [20, 0], [60, 0.1], [150, 0.5], [255, 0.9]],
                    "color": [[0, 0.2, 0.4, 1], [60, 0.4, 0.7, 1], [150, 1, 0.7, 0.3],
                              [255, 1, 1, 0.9]]},
                   (1.0, -0.6, 0.5), 110.0),
        "pet": lambda: (loaded("dicom-pet"), (3.5378182, 3.5378182, 3.375),
                {"opacity": [[0, 0], [1500, 0], [4000, 0.05], [10000, 0.4], [40000, 0.9],
                             [66261, 0.9]],
                 "color": [[0, 0.5, 0.05, 0], [4000, 0.8, 0.2, 0.05], [10000, 1, 0.6, 0.1],
                           [40000, 1, 1, 0.8], [66261, 1, 1, 1]]},
                (1.0, -0.4, 0.2), 950.0),
        # Two NIfTI files (NiBabel's test data): a small big-endian anatomical MR of 2 mm
        # voxels, magnified, and the first frame of a 4D series (2, 2, 2.2 mm).
        "nifti-anat": lambda: (loaded("nifti/anatomical.nii"), (2, 2, 2),
                       {"opacity": [[0, 0], [8000, 0], [10000, 0.3], [12500, 0.8],
                                    [14500, 0.9]],
                        "color": [[0, 0.8, 0.5, 0.4], [10000, 1, 0.85, 0.7], [14500, 1, 1, 1]]},
                       (1.0, -0.6, 0.4), 200.0),
        "nifti-4d": lambda: (loaded("nifti/example4d.nii.gz"), (2, 2, 2.2),
                     {"opacity": [[0, 0], [300, 0], [450, 0.3], [650, 0.8], [830, 0.9]],
                      "color": [[0, 0.8, 0.5, 0.4], [450, 1, 0.85, 0.7], [830, 1, 1, 1]]},
                     (0.8, -1.0, 0.5), 570.0),
    }


def camera(array, spacing, direction, distance, azimuth=0.0, elevation=0.0):
    nz, ny, nx = array.shape
    focal = np.array([(nx - 1) * spacing[0], (ny - 1) * spacing[1], (nz - 1) * spacing[2]]) / 2
    e = np.asarray(direction, float)
    e = e / np.linalg.norm(e)
    # Turned about the up axis (z) by `azimuth` degrees, then raised by `elevation` degrees
    # (clamped short of the pole).
    a = np.radians(azimuth)
    e = np.array([e[0] * np.cos(a) - e[1] * np.sin(a), e[0] * np.sin(a) + e[1] * np.cos(a), e[2]])
    lift = np.clip(np.arcsin(np.clip(e[2], -1, 1)) + np.radians(elevation), -1.4, 1.4)
    flat = np.hypot(e[0], e[1])
    e = np.array([e[0] / flat * np.cos(lift), e[1] / flat * np.cos(lift), np.sin(lift)])
    return focal, focal + distance * e / np.linalg.norm(e), (0.0, 0.0, 1.0)


def ray_cast_image(mapper):
    """The fixed-point mapper's own ray-cast image (premultiplied RGBA, 15-bit fixed point, one
    ray through each window pixel's centre), as [y (bottom row first), x, 4] floats, with its
    in-use size and origin in window pixels. Read from the mapper's memory: VTK's Python wrapping
    gives the buffer only as an address."""
    import ctypes
    image = mapper.GetRayCastImage()
    used, origin, memory = (image.GetImageInUseSize(), image.GetImageOrigin(),
                            image.GetImageMemorySize())
    if not (0 < used[0] <= memory[0] and 0 < used[1] <= memory[1]):
        sys.exit(f"crisp_compare.py: unexpected VTK ray-cast image sizes {used}, {memory}")
    address = int(image.GetImage().split("_")[1], 16)  # '_<hex>_p_void'
    count = memory[0] * memory[1] * 4
    buffer = (ctypes.c_uint16 * count).from_address(address)
    raw = np.ctypeslib.as_array(buffer).reshape(memory[1], memory[0], 4).astype(np.float64)
    return raw[:used[1], :used[0]], used, origin


def displayed(raw, used, origin, size):
    """What VTK 9.1's display helper makes of a ray-cast image (vtkOpenGLRayCastImageDisplayHelper,
    RenderTextureInternal): a quad over the in-use pixels whose texture coordinates run from the
    first texel's centre to the last one's, bilinear, so the picture is stretched by U / (U - 1)
    about the in-use image's centre. RGB in 8-bit levels, bottom row first."""
    out = np.zeros((size, size, 3))
    x = (np.arange(size) + 0.5 - origin[0]) * (used[0] - 1) / used[0]
    y = (np.arange(size) + 0.5 - origin[1]) * (used[1] - 1) / used[1]
    inside_x = (np.arange(size) >= origin[0]) & (np.arange(size) < origin[0] + used[0])
    inside_y = (np.arange(size) >= origin[1]) & (np.arange(size) < origin[1] + used[1])
    x, y = np.clip(x, 0, used[0] - 1), np.clip(y, 0, used[1] - 1)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    x1, y1 = np.minimum(x0 + 1, used[0] - 1), np.minimum(y0 + 1, used[1] - 1)
    fx, fy = (x - x0)[None, :, None], (y - y0)[:, None, None]
    rgb = raw[..., :3] * 255.0 / 32767.0
    s = (rgb[y0][:, x0] * (1 - fx) * (1 - fy) + rgb[y0][:, x1] * fx * (1 - fy) +
         rgb[y1][:, x0] * (1 - fx) * fy + rgb[y1][:, x1] * fx * fy)
    out[np.ix_(inside_y, inside_x)] = s[np.ix_(inside_y, inside_x)]
    return out


def vtk_render(array, spacing, tf, cam, repeats, picture="rays", sample_distance=0.25,
               shading=False):
    # VTK's GL and ewaview's OSMesa do not share a process: this runs in a child (--vtk).
    # picture "window": the window as VTK shows it; "rays": the ray caster's own image (one ray
    # through each pixel's centre), without the display's stretch by U / (U - 1) (displayed());
    # "gpu": VTK's GPU ray caster's window.
    try:
        from vtkmodules.util import numpy_support
        from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
        from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,
                                                 vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                                 vtkWindowToImageFilter)
        from vtkmodules.vtkRenderingVolume import vtkFixedPointVolumeRayCastMapper
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
        import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
    except ImportError as e:
        print(f"crisp_compare.py: VTK not available ({e})", file=sys.stderr)
        sys.exit(3)
    image = vtkImageData()
    nz, ny, nx = array.shape
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*spacing)
    image.SetOrigin(0, 0, 0)
    flat = np.ascontiguousarray(array).ravel()
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(flat, deep=True))
    opacity = vtkPiecewiseFunction()
    for v, a in tf["opacity"]:
        opacity.AddPoint(v, a)
    color = vtkColorTransferFunction()
    for v, r, g, b in tf["color"]:
        color.AddRGBPoint(v, r, g, b)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetInterpolationTypeToLinear()
    if shading:  # ewaview's head light (--ambient, --diffuse, --specular, --shininess defaults)
        prop.ShadeOn()
        prop.SetAmbient(0.3)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.25)
        prop.SetSpecularPower(24.0)
    else:
        prop.ShadeOff()
    if picture == "gpu":  # a cross-check of the geometry: GL's own projection, no display step
        from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
        mapper = vtkOpenGLGPUVolumeRayCastMapper()
    else:
        mapper = vtkFixedPointVolumeRayCastMapper()
        mapper.SetImageSampleDistance(1.0)
    mapper.SetInputData(image)
    mapper.SetAutoAdjustSampleDistances(0)
    mapper.SetSampleDistance(sample_distance * min(spacing))
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(SIZE, SIZE)
    focal, position, up = cam
    c = ren.GetActiveCamera()
    c.SetFocalPoint(*focal)
    c.SetPosition(*position)
    c.SetViewUp(*up)
    c.SetViewAngle(30.0)
    ren.ResetCameraClippingRange()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        win.Render()
        times.append(time.perf_counter() - start)
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    out = grab.GetOutput()
    w, h, _ = out.GetDimensions()
    rgb = numpy_support.vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, 3)
    if picture == "rays":
        raw, used, origin = ray_cast_image(mapper)
        # The image read must be the one shown: the window holds it stretched as displayed()
        # says, to rounding (measured: mean 0.15, largest 0.5 levels); otherwise stop.
        error = np.abs(displayed(raw, used, origin, SIZE) - rgb.astype(np.float64))
        if error.mean() > 0.5 or error.max() > 2.0:
            sys.exit(f"crisp_compare.py: VTK's ray-cast image does not match its window "
                     f"(mean {error.mean():.2f}, largest {error.max():.2f} levels)")
        rgb = np.zeros((SIZE, SIZE, 3), np.uint8)
        rgb[origin[1]:origin[1] + used[1], origin[0]:origin[0] + used[0]] = np.rint(
            np.clip(raw[..., :3] * 255.0 / 32767.0, 0, 255)).astype(np.uint8)
    return rgb[::-1].copy(), 1000.0 * statistics.median(times)


def luminance(rgb):
    x = rgb.astype(np.float64) / 255.0
    return 0.2126 * x[..., 0] + 0.7152 * x[..., 1] + 0.0722 * x[..., 2]


def blur(x, sigma=1.5, radius=5):
    k = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    k /= k.sum()
    p = np.pad(x, radius, mode="reflect")
    rows = sum(k[i] * p[:, i:i + x.shape[1]] for i in range(2 * radius + 1))
    return sum(k[i] * rows[i:i + x.shape[0], :] for i in range(2 * radius + 1))


def ssim(a, b):
    """Mean SSIM (Wang et al. 2004: Gaussian window sigma 1.5, K1 0.01, K2 0.03, L 1)."""
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    ma, mb = blur(a), blur(b)
    va, vb = blur(a * a) - ma * ma, blur(b * b) - mb * mb
    cov = blur(a * b) - ma * mb
    s = ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2))
    return float(s.mean())


def gradient(x):
    gy, gx = np.gradient(x)
    return np.hypot(gx, gy)


# A view whose ray-cast picture has no edge steeper than this (luminance a pixel, at its 99th
# percentile) is flat: a smooth field (hydrogen), or a surface filling the picture, where the
# "edges" sharpness weighs are the ray caster's own sampling steps (CThead at 180:0:0.6 0.004,
# bonsai's pot at 300:20:1 0.024; close-ups with structure 0.2 to 0.5).
FLAT_GRADIENT = 0.05


def is_flat(ref):
    return float(np.percentile(gradient(ref), 99)) < FLAT_GRADIENT


def sharpness(ours, ref):
    """Mean gradient over the reference's edges (>= 25% of its 99th percentile), ours / ref."""
    g_ref, g_ours = gradient(ref), gradient(ours)
    edges = g_ref >= 0.25 * np.percentile(g_ref, 99)
    return float(g_ours[edges].mean() / g_ref[edges].mean())


def vtk_child(name, out, repeats, scale, azimuth, elevation, picture, sample_distance, shading):
    array, spacing, tf, direction, distance = volumes()[name]()
    rgb, ms = vtk_render(array, spacing, tf,
                         camera(array, spacing, direction, distance * scale, azimuth, elevation),
                         repeats, picture, sample_distance, shading)
    np.save(out, rgb)
    print(f"{ms:.3f}")


def vtk_picture(name, repeats, scale, azimuth, elevation, picture="rays", sample_distance=0.25,
                shading=False):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "vtk.npy")
        run = subprocess.run([sys.executable, os.path.abspath(__file__), "--vtk", name, out,
                              "--repeats", str(repeats), "--distance-scale", str(scale),
                              "--azimuth", str(azimuth), "--elevation", str(elevation),
                              "--vtk-picture", picture,
                              "--vtk-sample-distance", str(sample_distance)] +
                             (["--shading"] if shading else []),
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"crisp_compare.py: VTK failed on {name}: {run.stderr.strip()}")
        return np.load(out), float(run.stdout.split()[-1])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--vtk", nargs=2, metavar=("VOLUME", "NPY"), help=argparse.SUPPRESS)
    p.add_argument("--out", help="folder for the pictures (with --views: ours and VTK's at each "
                                 "view) and montages")
    p.add_argument("--volumes", default="aneurism,bonsai,engine,CThead,tooth",
                   help="comma-separated; also mrbrain, lidc2, walnut, fetal-t2, hydrogen, "
                        "headsq, headmr, nucleon")
    p.add_argument("--widths", default="1,0.85,0.7")
    p.add_argument("--classifications", default="pre,post,post-mean",
                   help="pre, post (pre-integrated between slabs), post-mean (each slab's mean "
                        "value alone: --slab-preintegration off)")
    p.add_argument("--cutoff", type=float, default=4.0)
    p.add_argument("--depth-cutoff", help="ewaview's --depth-cutoff (default: ewaview's, 1)")
    p.add_argument("--prefilters", default=None,
                   help="post: ewaview's --prefilter values to compare, comma-separated "
                        "(default: ewaview's, 0.04)")
    p.add_argument("--slab-thickness", type=float, default=2.0,
                   help="slab thickness in voxels (ewaview's default 2)")
    p.add_argument("--low-pass", type=float,
                   help="ewaview's --low-pass: the EWA screen filter's variance (default: ewaview's)")
    p.add_argument("--slab-samples", type=int, choices=[2, 4],
                   help="ewaview's --slab-samples (default: ewaview's, 4)")
    p.add_argument("--slab-resolution", choices=["auto", "full"],
                   help="ewaview's --slab-resolution (default: ewaview's, auto)")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--distance-scale", type=float, default=1.0,
                   help="camera distance times this (1: the close-ups, 2 to 3 pixels a voxel; "
                        "3: about one pixel a voxel)")
    p.add_argument("--azimuth", type=float, default=0.0,
                   help="turn each view's eye about the up axis by this many degrees (views "
                        "not in the list)")
    p.add_argument("--elevation", type=float, default=0.0,
                   help="raise each view's eye by this many degrees")
    p.add_argument("--vtk-picture", choices=["rays", "window", "gpu"], default="rays",
                   help="the reference: rays, VTK's CPU ray-cast image (one ray through each "
                        "pixel's centre; default); window, its window as VTK shows it, which its "
                        "display stretches by U / (U - 1) about the in-use image's centre (384/383 "
                        "for a view that fills the 384-pixel window); gpu, VTK's GPU ray caster "
                        "(vtkOpenGLGPUVolumeRayCastMapper) instead, as a cross-check")
    p.add_argument("--vtk-sample-distance", type=float, default=0.25,
                   help="VTK's sample distance along its rays in voxel spacings (the issue's "
                        "0.25; finer shows fewer of its wood-grain rings)")
    p.add_argument("--shading", action="store_true",
                   help="both renderers shade with a head light (ewaview's default light terms, "
                        "set on VTK's volume property too)")
    p.add_argument("--post-normals", choices=["ray", "field", "voxel"],
                   help="with --shading: ewaview's --post-normals for post-classified variants "
                        "(default: ewaview's, ray)")
    p.add_argument("--views",
                   help="several views AZIMUTH:ELEVATION:DISTANCE-SCALE, comma-separated (e.g. "
                        "0:0:1,120:0:1); prints each variant's SSIM per view with the worst and "
                        "the mean instead of one view's table")
    a = p.parse_args()
    if not a.vtk_sample_distance > 0:
        p.error(f"--vtk-sample-distance: {a.vtk_sample_distance:g} is not a positive length")
    unknown = [n for n in a.volumes.split(",") if n not in volumes()]
    if unknown and not a.vtk:
        p.error(f"--volumes: unknown volume {unknown[0]} (known: {', '.join(volumes())})")
    if a.vtk:
        return vtk_child(a.vtk[0], a.vtk[1], a.repeats, a.distance_scale, a.azimuth,
                         a.elevation, a.vtk_picture, a.vtk_sample_distance, a.shading)
    import ewaview
    widths = [float(w) for w in a.widths.split(",")]
    prefilters = [None] if a.prefilters is None else [float(b) for b in a.prefilters.split(",")]
    variants = [(c, w, b) for c in a.classifications.split(",") for w in widths
                for b in (prefilters if c.startswith("post") else [None])]
    if a.out:
        os.makedirs(a.out, exist_ok=True)
    if a.views:
        return compare_views(a, variants, [tuple(float(x) for x in v.split(":"))
                                           for v in a.views.split(",")])
    print(f"| volume | classification | kernel width | prefilter | SSIM | sharpness | ms/frame |")
    print(f"| --- | --- | --- | --- | --- | --- | --- |")
    all_vols = volumes()
    for name in a.volumes.split(","):
        array, spacing, tf, direction, distance = all_vols[name]()
        cam = camera(array, spacing, direction, distance * a.distance_scale, a.azimuth,
                     a.elevation)
        ref, vtk_ms = vtk_picture(name, a.repeats, a.distance_scale, a.azimuth, a.elevation,
                                  a.vtk_picture, a.vtk_sample_distance, a.shading)
        ref_y = luminance(ref)
        print(f"| {name} | VTK ray caster | | | 1 | 1 | {vtk_ms:.0f} |", flush=True)
        scene = make_scene(array, spacing, tf, cam, a.cutoff)
        pictures = [ref]
        for classification, width, prefilter in variants:
            shown, tag, options = variant_options(a, classification, width, prefilter)
            img = scene.render(**options)  # classifies
            times = []
            for _ in range(a.repeats):
                start = time.perf_counter()
                img = scene.render(**options)
                times.append(time.perf_counter() - start)
            y = luminance(img)
            print(f"| {name} | {classification} | {width:g} | {shown} | {ssim(y, ref_y):.3f} | "
                  f"{sharpness(y, ref_y):.2f} | {1000 * statistics.median(times):.0f} |",
                  flush=True)
            pictures.append(img)
            if a.out:
                ewaview.write_png(f"{a.out}/{name}_{tag}.png", img)
        if a.out:
            ewaview.write_png(f"{a.out}/{name}_vtk.png", ref)
            ewaview.write_png(f"{a.out}/{name}_montage.png", np.concatenate(pictures, axis=1))


def make_scene(array, spacing, tf, cam, cutoff):
    import ewaview
    scene = ewaview.Scene(array, spacing=spacing, resolution=(SIZE, SIZE),
                          camera_position=tuple(cam[1]), camera_focal_point=tuple(cam[0]),
                          camera_view_up=cam[2], background=(0, 0, 0), cutoff=cutoff)
    scene.transfer_function = dict(tf, opacity_unit_distance=1.0)
    return scene


def variant_options(a, classification, width, prefilter):
    """(prefilter as shown, file tag, Scene.render keywords) of one variant."""
    options = dict(classification=classification.split("-")[0], kernel_width=width,
                   slab_thickness=a.slab_thickness)
    if classification == "post-mean":
        options["slab_preintegration"] = "off"
    if a.depth_cutoff:
        options["depth_cutoff"] = a.depth_cutoff
    if a.slab_resolution:
        options["slab_resolution"] = a.slab_resolution
    if a.low_pass:
        options["low_pass"] = a.low_pass
    if a.slab_samples and classification == "post":
        options["slab_samples"] = a.slab_samples
    if prefilter is not None:
        options["prefilter"] = prefilter
    if a.shading:
        options["shading"] = True
        if a.post_normals and classification.startswith("post"):
            options["post_normals"] = a.post_normals
    shown = "" if not classification.startswith("post") else (
        "default" if prefilter is None else f"{prefilter:g}")
    tag = f"{classification}_{width:g}" + ("" if prefilter is None else f"_p{prefilter:g}")
    return shown, tag, options


def compare_views(a, variants, views):
    """Each variant of each volume at several views: SSIM / sharpness per view, the worst SSIM and
    the mean, the worst sharpness."""
    import ewaview
    names = " | ".join(f"{az:g}:{el:g}:{sc:g}" for az, el, sc in views)
    print(f"| volume | classification | kernel width | prefilter | {names} | worst | mean | "
          f"worst sharpness | worst sharpness, views with edges |")
    print("| --- " * (len(views) + 8) + "|")
    all_vols = volumes()
    any_flat = False
    for name in a.volumes.split(","):
        array, spacing, tf, direction, distance = all_vols[name]()
        scores = {v: [] for v in variants}
        flat = []
        for az, el, sc in views:
            cam = camera(array, spacing, direction, distance * sc, az, el)
            ref = vtk_picture(name, 1, sc, az, el, a.vtk_picture, a.vtk_sample_distance,
                              a.shading)[0]
            ref_y = luminance(ref)
            flat.append(is_flat(ref_y))
            any_flat = any_flat or flat[-1]
            if a.out:
                ewaview.write_png(f"{a.out}/{name}_vtk_{az:g}_{el:g}_{sc:g}.png", ref)
            scene = make_scene(array, spacing, tf, cam, a.cutoff)
            for v in variants:
                shown, tag, options = variant_options(a, *v)
                img = scene.render(**options)
                y = luminance(img)
                scores[v].append((ssim(y, ref_y), sharpness(y, ref_y)))
                if a.out:
                    ewaview.write_png(f"{a.out}/{name}_{tag}_{az:g}_{el:g}_{sc:g}.png", img)
        for v in variants:
            shown = variant_options(a, *v)[0]
            s = [x for x, _ in scores[v]]
            cells = " | ".join(f"{x:.4f} / {h:.2f}{'*' if f else ''}"
                               for (x, h), f in zip(scores[v], flat))
            edged = [h for (_, h), f in zip(scores[v], flat) if not f]
            print(f"| {name} | {v[0]} | {v[1]:g} | {shown} | {cells} | {min(s):.4f} | "
                  f"{statistics.mean(s):.4f} | {min(h for _, h in scores[v]):.2f} | "
                  f"{f'{min(edged):.2f}' if edged else '-'} |", flush=True)
    if any_flat:
        print(f"\n\\* flat view: VTK's picture has no luminance step above {FLAT_GRADIENT:g} a "
              "pixel (99th percentile): the edges sharpness weighs are faint (a smooth field, or "
              "a surface filling the picture with the ray caster's sampling steps on it)")


if __name__ == "__main__":
    main()

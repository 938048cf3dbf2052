#!/usr/bin/python3
"""Times VTK's CPU or GPU ray caster on the views ewaview's benchmarks draw.

Called by ewaview-shearwarp-bench and ewaview-compare with a raw volume (native little-endian,
x fastest, first row at the bottom as in ewaview) and an ewaview transfer-function JSON, so VTK
sees the same data, transfer function, image size and views. Two ways to give the views:
  --views AZ,...            a turntable: parallel projection, VTK's reset camera, then these
                            azimuths (degrees) about the vertical axis, each timed once;
  --camera P,F,U --view-angle DEG [--parallel]
                            one fixed camera (position, focal point, view-up: 9 numbers in the
                            volume's own frame) drawn --repeats times after a warm-up frame.
--mapper cpu (vtkFixedPointVolumeRayCastMapper, the default) or gpu (vtkGPUVolumeRayCastMapper).
--image PATH writes the last frame as PNG. Prints one line:
  vtk <mean wall s> <mean CPU s, all threads> <frames> <median wall s>
Needs python3-vtk9 (scripts/install_bench_deps.sh) and a display (the benchmarks run it under
xvfb-run when DISPLAY is unset). Exit status 3: VTK is not installed.
"""
import argparse
import json
import math
import statistics
import sys
import time

try:
    from vtkmodules.vtkIOImage import vtkImageReader2, vtkPNGWriter
    from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT, VTK_FLOAT
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,
                                             vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                             vtkWindowToImageFilter)
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingVolume import (vtkFixedPointVolumeRayCastMapper,
                                               vtkGPUVolumeRayCastMapper)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (render window implementation)
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (GPU mapper, ray-cast display)
except ImportError as e:
    print(f"vtk_raycast_bench.py: VTK not available ({e})", file=sys.stderr)
    sys.exit(3)

TYPES = {"uint8": VTK_UNSIGNED_CHAR, "int16": VTK_SHORT, "uint16": VTK_UNSIGNED_SHORT,
         "float32": VTK_FLOAT}


def numbers(text, count, name):
    values = [float(x) for x in text.split(",")]
    if len(values) != count:
        raise SystemExit(f"vtk_raycast_bench.py: --{name} needs {count} numbers, got {text}")
    return values


def read_volume(a):
    dims = [int(x) for x in numbers(a.dims, 3, "dims")]
    reader = vtkImageReader2()
    reader.SetFileName(a.raw)
    reader.SetFileDimensionality(3)
    reader.SetDataScalarType(TYPES[a.type])
    reader.SetDataByteOrderToLittleEndian()
    # The file's first row is y = 0, as ewaview stores it; VTK's default (upper left) would
    # read the rows bottom up and draw every slice mirrored in y.
    reader.SetFileLowerLeft(1)
    reader.SetDataExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1)
    reader.SetDataSpacing(*numbers(a.spacing, 3, "spacing"))
    reader.SetDataOrigin(*numbers(a.origin, 3, "origin"))
    reader.Update()
    return reader


def volume_property(path, shade=None):
    """The transfer function's property; `shade` (ambient, diffuse, specular, power): lit by
    the renderer's head light from the gradient, as ewaview's --shading."""
    tf = json.load(open(path))
    opacity = vtkPiecewiseFunction()
    for v, alpha in tf["opacity"]:
        opacity.AddPoint(v, alpha)
    color = vtkColorTransferFunction()
    points = tf.get("color") or [[p[0], 1.0, 1.0, 1.0] for p in tf["opacity"]]
    for v, r, g, b in points:
        color.AddRGBPoint(v, r, g, b)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(tf.get("opacity_unit_distance", 1.0))
    prop.SetInterpolationTypeToLinear()
    if shade is None:
        prop.ShadeOff()
    else:
        prop.ShadeOn()
        prop.SetAmbient(shade[0])
        prop.SetDiffuse(shade[1])
        prop.SetSpecular(shade[2])
        prop.SetSpecularPower(shade[3])
    return prop


def timed_render(win, times, cpu):
    start, cpu0 = time.perf_counter(), time.process_time()
    win.Render()
    # The GPU mapper only queues GL work; wait for it as ewaview's timings do.
    if hasattr(win, "WaitForCompletion"):
        win.WaitForCompletion()
    times.append(time.perf_counter() - start)
    cpu.append(time.process_time() - cpu0)


def save_png(win, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("raw")
    p.add_argument("--dims", required=True)
    p.add_argument("--type", required=True, choices=TYPES)
    p.add_argument("--spacing", required=True)
    p.add_argument("--origin", default="0,0,0")
    p.add_argument("--tf", required=True)
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--views", help="comma-separated azimuths in degrees (turntable)")
    p.add_argument("--camera", help="position,focal point,view-up: 9 numbers")
    p.add_argument("--view-angle", type=float, default=30.0)
    p.add_argument("--parallel", action="store_true")
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--mapper", choices=["cpu", "gpu"], default="cpu")
    p.add_argument("--image")
    p.add_argument("--shade", help="ambient,diffuse,specular,power: shaded (default: unshaded)")
    a = p.parse_args()
    if (a.views is None) == (a.camera is None):
        raise SystemExit("vtk_raycast_bench.py: give one of --views and --camera")

    reader = read_volume(a)
    if a.mapper == "cpu":
        mapper = vtkFixedPointVolumeRayCastMapper()
    else:
        mapper = vtkGPUVolumeRayCastMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    shade = numbers(a.shade, 4, "shade") if a.shade else None
    volume.SetProperty(volume_property(a.tf, shade))
    ren = vtkRenderer()
    ren.SetBackground(0.0, 0.0, 0.0)
    ren.AddVolume(volume)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(a.size, a.size)
    cam = ren.GetActiveCamera()
    times, cpu = [], []
    if a.camera is not None:
        c = numbers(a.camera, 9, "camera")
        cam.SetPosition(*c[0:3])
        cam.SetFocalPoint(*c[3:6])
        cam.SetViewUp(*c[6:9])
        cam.SetViewAngle(a.view_angle)
        if a.parallel:
            cam.ParallelProjectionOn()
            distance = math.dist(c[0:3], c[3:6])
            cam.SetParallelScale(distance * math.tan(math.radians(a.view_angle) / 2))
        ren.ResetCameraClippingRange()
        timed_render(win, [], [])  # warm-up: upload, shader compilation, not timed
        for _ in range(max(1, a.repeats)):
            timed_render(win, times, cpu)
    else:
        cam.ParallelProjectionOn()
        ren.ResetCamera()
        win.Render()  # first frame: set-up, not timed
        last = 0.0
        for az in [float(x) for x in a.views.split(",")]:
            cam.Azimuth(az - last)
            last = az
            ren.ResetCameraClippingRange()
            timed_render(win, times, cpu)
    if a.image:
        save_png(win, a.image)
    print(f"vtk {statistics.mean(times):.5f} {statistics.mean(cpu):.5f} {len(times)} "
          f"{statistics.median(times):.5f}")


if __name__ == "__main__":
    main()

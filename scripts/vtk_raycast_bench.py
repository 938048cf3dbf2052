#!/usr/bin/python3
"""Times VTK's CPU ray caster (vtkFixedPointVolumeRayCastMapper) on a turntable.

Called by ewaview-shearwarp-bench with a raw volume (native little-endian) and an ewaview
transfer-function JSON, so VTK sees the same data, transfer function, image size and views
(parallel projection, rotation about the vertical axis). Prints one line:
  vtk <wall seconds per frame> <CPU seconds per frame, all threads> <frames>  (means)
Needs python3-vtk9 and a display (the bench runs it under xvfb-run when DISPLAY is unset).
"""
import argparse
import json
import statistics
import sys
import time

try:
    from vtkmodules.vtkIOImage import vtkImageReader2
    from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT, VTK_FLOAT
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,
                                             vtkRenderWindow, vtkVolume, vtkVolumeProperty)
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingVolume import vtkFixedPointVolumeRayCastMapper
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (render window implementation)
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (ray-cast image display helper)
except ImportError as e:
    print(f"vtk_raycast_bench.py: VTK not available ({e})", file=sys.stderr)
    sys.exit(3)

TYPES = {"uint8": VTK_UNSIGNED_CHAR, "int16": VTK_SHORT, "uint16": VTK_UNSIGNED_SHORT,
         "float32": VTK_FLOAT}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("raw")
    p.add_argument("--dims", required=True)
    p.add_argument("--type", required=True, choices=TYPES)
    p.add_argument("--spacing", required=True)
    p.add_argument("--tf", required=True)
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--views", required=True, help="comma-separated azimuths in degrees")
    a = p.parse_args()
    dims = [int(x) for x in a.dims.split(",")]
    spacing = [float(x) for x in a.spacing.split(",")]

    reader = vtkImageReader2()
    reader.SetFileName(a.raw)
    reader.SetFileDimensionality(3)
    reader.SetDataScalarType(TYPES[a.type])
    reader.SetDataByteOrderToLittleEndian()
    reader.SetDataExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1)
    reader.SetDataSpacing(*spacing)
    reader.Update()

    tf = json.load(open(a.tf))
    opacity = vtkPiecewiseFunction()
    for v, alpha in tf["opacity"]:
        opacity.AddPoint(v, alpha)
    color = vtkColorTransferFunction()
    for v, r, g, b in tf["color"]:
        color.AddRGBPoint(v, r, g, b)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(tf.get("opacity_unit_distance", 1.0))
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()

    mapper = vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.AddVolume(volume)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(a.size, a.size)
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    ren.ResetCamera()
    win.Render()  # first frame: set-up, not timed
    times = []
    cpu = []
    last = 0.0
    for az in [float(x) for x in a.views.split(",")]:
        cam.Azimuth(az - last)
        last = az
        start, cpu0 = time.perf_counter(), time.process_time()
        win.Render()
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - cpu0)
    print(f"vtk {statistics.mean(times):.4f} {statistics.mean(cpu):.4f} {len(times)}")


if __name__ == "__main__":
    main()

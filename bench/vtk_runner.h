// VtkRunner: VTK's ray casters timed through scripts/vtk_raycast_bench.py on a volume and
// transfer function the benchmarks hand over as files.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/shading.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

struct VtkTiming {
  bool ok = false;
  double meanSeconds = -1.0;    // wall seconds per timed frame
  double cpuSeconds = -1.0;     // CPU seconds per timed frame, all threads of the script
  double medianSeconds = -1.0;  // wall
  int frames = 0;
  std::string error;  // the script's first line of output when !ok
};

// The script's arguments for the view `camera` draws of `volume`: the camera moved into the
// volume's own frame (where the raw file's voxels lie), its view angle and projection.
std::vector<std::string> vtkCameraArguments(const Camera& camera, const Volume& volume);

// The script's arguments for `lighting` (--shading's head light): none where it is off.
std::vector<std::string> vtkLightingArguments(const Lighting& lighting);

// Writes the volume (raw, little-endian) and transfer function to unique temporary files for
// as long as it lives, and runs the script on them (under xvfb-run when DISPLAY is unset).
class VtkRunner {
 public:
  // `script`: path of vtk_raycast_bench.py; empty: the one in the source tree.
  VtkRunner(const Volume& volume, const TransferFunction& tf, std::string script = "");
  ~VtkRunner();
  VtkRunner(const VtkRunner&) = delete;
  VtkRunner& operator=(const VtkRunner&) = delete;

  // Runs the script with the volume's arguments plus `arguments` (e.g. --size, --mapper,
  // --camera or --views). A failure (no VTK, no display) comes back as !ok with the reason.
  VtkTiming run(const std::vector<std::string>& arguments) const;

  // The source tree's scripts/vtk_raycast_bench.py.
  static std::string defaultScript();

 private:
  std::string script_, raw_, tf_, out_;
  std::vector<std::string> volumeArguments_;
};

}  // namespace ewa

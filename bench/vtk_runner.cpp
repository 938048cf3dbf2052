// VtkRunner: temporary input files, the script's command line and its one-line answer.
#include "bench/vtk_runner.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/volume_orientation.h"
#include "io/transfer_function_io.h"

namespace ewa {
namespace {

std::string triple(const glm::dvec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return text;
}

// Single quotes for the shell: every argument is a path or numbers, but paths may hold spaces.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::vector<std::string> vtkCameraArguments(const Camera& camera, const Volume& volume) {
  const Camera local = cameraInVolumeFrame(camera, volume);
  std::vector<std::string> args = {
      "--camera",
      triple(local.position) + "," + triple(local.focalPoint) + "," + triple(local.viewUp),
      "--view-angle", std::to_string(local.viewAngleDeg)};
  if (local.orthographic) args.push_back("--parallel");
  return args;
}

std::vector<std::string> vtkLightingArguments(const Lighting& lighting) {
  if (!lighting.enabled) return {};
  return {"--shade", std::to_string(lighting.ambient) + "," + std::to_string(lighting.diffuse) +
                         "," + std::to_string(lighting.specular) + "," +
                         std::to_string(lighting.shininess)};
}

std::string VtkRunner::defaultScript() {
  return std::string(EWA_ASSET_DIR) + "/../scripts/vtk_raycast_bench.py";
}

VtkRunner::VtkRunner(const Volume& volume, const TransferFunction& tf, std::string script)
    : script_(script.empty() ? defaultScript() : std::move(script)) {
  // Unique per process: several benchmarks may run side by side.
  const std::string stem =
      (std::filesystem::temp_directory_path() / ("ewaview_vtk_" + std::to_string(getpid())))
          .string();
  raw_ = stem + ".raw";
  tf_ = stem + ".tf.json";
  out_ = stem + ".txt";
  std::ofstream raw(raw_, std::ios::binary);
  raw.write(reinterpret_cast<const char*>(volume.bytes().data()),
            std::streamsize(volume.bytes().size()));
  if (!raw) throw std::runtime_error(raw_ + ": cannot write the volume for VTK");
  saveTransferFunction(tf_, tf);
  const auto& d = volume.dims();
  volumeArguments_ = {
      raw_,
      "--dims",
      std::to_string(d[0]) + "," + std::to_string(d[1]) + "," + std::to_string(d[2]),
      "--type",
      scalarName(volume.type()),
      "--spacing",
      triple(volume.spacing()),
      "--origin",
      triple(volume.origin()),
      "--tf",
      tf_};
}

VtkRunner::~VtkRunner() {
  std::error_code ignored;
  for (const std::string& path : {raw_, tf_, out_}) std::filesystem::remove(path, ignored);
}

VtkTiming VtkRunner::run(const std::vector<std::string>& arguments) const {
  std::string cmd = std::getenv("DISPLAY") ? "" : "xvfb-run -a -s '-screen 0 1024x768x24' ";
  // Debian's python3-vtk9 belongs to the system interpreter, not to one first on PATH.
  cmd += "/usr/bin/python3 " + quoted(script_);
  for (const std::string& a : volumeArguments_) cmd += " " + quoted(a);
  for (const std::string& a : arguments) cmd += " " + quoted(a);
  cmd += " >" + quoted(out_) + " 2>&1";
  const int status = std::system(cmd.c_str());
  VtkTiming t;
  std::ifstream in(out_);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word;
    if (words >> word && word == "vtk" &&
        words >> t.meanSeconds >> t.cpuSeconds >> t.frames >> t.medianSeconds) {
      t.ok = status == 0;
      break;
    }
    if (t.error.empty()) t.error = line;
  }
  if (!t.ok && t.error.empty())
    t.error = "vtk_raycast_bench.py gave no timing (exit status " + std::to_string(status) + ")";
  return t;
}

}  // namespace ewa

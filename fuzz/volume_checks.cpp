// Loading fuzz inputs as volume files and checking what comes out.
#include "volume_checks.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "core/splat_set.h"
#include "core/transfer_function.h"
#include "core/volume_orientation.h"
#include "fuzz_case.h"
#include "io/volume_loader.h"
#include "io/volume_writer.h"

namespace ewa::fuzz {

namespace {
// Splat classification runs per voxel; keep iterations fast on large (but valid) inputs.
constexpr int64_t kMaxCheckedVoxels = int64_t{1} << 20;
}  // namespace

void checkVolume(const Volume& v) {
  const auto& d = v.dims();
  EWA_FUZZ_CHECK(d[0] > 0 && d[1] > 0 && d[2] > 0);
  EWA_FUZZ_CHECK(v.bytes().size() == size_t(v.voxelCount()) * scalarSize(v.type()));
  for (int a = 0; a < 3; ++a) {
    EWA_FUZZ_CHECK(std::isfinite(v.spacing()[a]) && v.spacing()[a] > 0.0);
    EWA_FUZZ_CHECK(std::isfinite(v.origin()[a]));
  }
  // The direction loaders leave: a rotation (renderers move the camera by its inverse).
  EWA_FUZZ_CHECK(isOrthonormal(v.direction(), 1e-6) && glm::determinant(v.direction()) > 0.0);
  EWA_FUZZ_CHECK(std::isfinite(v.minValue()) && std::isfinite(v.maxValue()));
  EWA_FUZZ_CHECK(v.minValue() <= v.maxValue());
  const uint64_t counted = std::accumulate(v.histogram().begin(), v.histogram().end(), uint64_t{0});
  EWA_FUZZ_CHECK(counted <= uint64_t(v.voxelCount()));
  if (v.voxelCount() > kMaxCheckedVoxels || d[0] > 65535 || d[1] > 65535 || d[2] > 65535) return;
  const TransferFunction tf = defaultTransferFunction(v);
  tf.validate();
  const SplatSet splats = SplatSet::build(v, [&](double x) { return tf.alphaAt(x) > 0.0; });
  EWA_FUZZ_CHECK(splats.size() <= size_t(v.voxelCount()));
  for (const PackedSplat& s : splats.splats()) {
    EWA_FUZZ_CHECK(SplatSet::i(s) < d[0] && SplatSet::j(s) < d[1] && SplatSet::k(s) < d[2]);
    const double x = v.value(SplatSet::i(s), SplatSet::j(s), SplatSet::k(s));
    EWA_FUZZ_CHECK(std::isfinite(x));  // NaN and infinity are never splatted
  }
}

void checkWrittenBack(const Volume& v, const std::string& folder) {
  if (v.voxelCount() > (int64_t{1} << 16)) return;
  for (const char* name : {"back.nrrd", "back.nii", "back.mha", "back.mhd", "back.tif"}) {
    const std::string path = folder + "/" + name;
    const bool nifti = savedVolumeFormat(path) == SavedVolumeFormat::Nifti;
    const bool tiff = savedVolumeFormat(path) == SavedVolumeFormat::Tiff;
    try {
      writeVolume(path, v);
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EWA_FUZZ_CHECK(nifti);  // NRRD, MetaImage and TIFF hold every volume
      EWA_FUZZ_CHECK(message.rfind(path + ": ", 0) == 0);
      EWA_FUZZ_CHECK(message.find('\n') == std::string::npos);
      continue;
    }
    const Volume back = loadVolume(path);  // a LoadError here is a bug: escapes as one
    EWA_FUZZ_CHECK(back.dims() == v.dims() && back.type() == v.type());
    EWA_FUZZ_CHECK(back.bytes() == v.bytes());
    if (tiff) {  // the spacing and origin to the last digit, on the world's axes
      EWA_FUZZ_CHECK(back.spacing() == v.spacing() && back.direction() == glm::dmat3(1.0));
      for (int a = 0; a < 3; ++a)  // (a subnormal origin may read back as 0)
        EWA_FUZZ_CHECK(std::abs(back.origin()[a] - v.origin()[a]) <= 1e-300);
      // The unit too, unless a note says OME has none of that name.
      const std::vector<std::string> losses = savedVolumeLosses(path, v);
      EWA_FUZZ_CHECK(back.unit() == v.unit() ||
                     (back.unit().empty() &&
                      std::any_of(losses.begin(), losses.end(), [](const std::string& loss) {
                        return loss.find("has no unit") != std::string::npos;
                      })));
      continue;
    }
    // Every voxel at the same place: each axis's step (direction times spacing) and the origin.
    // (The parts may differ: a direction a loader kept within its tolerance of a rotation comes
    // back with unit columns.) NRRD's and MetaImage's text keep doubles; NIfTI-1 rounds them
    // to float32.
    const double relative = nifti ? 1e-6 : 1e-12;
    double extent = glm::length(v.origin());
    for (int a = 0; a < 3; ++a) {
      const glm::dvec3 step = v.direction()[a] * v.spacing()[a];
      const glm::dvec3 stepBack = back.direction()[a] * back.spacing()[a];
      const double size = std::hypot(step.x, step.y, step.z);
      const glm::dvec3 d = stepBack - step;
      EWA_FUZZ_CHECK(std::hypot(d.x, d.y, d.z) <= relative * size);
      extent = std::max(extent, size * double(v.dims()[size_t(a)]));
    }
    for (int a = 0; a < 3; ++a)
      EWA_FUZZ_CHECK(std::abs(back.origin()[a] - v.origin()[a]) <= relative * extent + 1e-300);
    if (!nifti) EWA_FUZZ_CHECK(back.patientFrame() == v.patientFrame());
  }
}

void fuzzVolumeFile(const uint8_t* data, size_t size, const std::string& extension) {
  // One folder per process; inputs overwrite the same few files.
  static ScratchFiles files;
  const std::string path = files.write(data, size, "in" + extension);
  Volume volume;
  try {
    volume = loadVolume(path);
  } catch (const LoadError& e) {
    // The promise: one line naming the file.
    const std::string message = e.what();
    EWA_FUZZ_CHECK(message.rfind(path + ": ", 0) == 0);
    EWA_FUZZ_CHECK(message.find('\n') == std::string::npos);
    return;
  }
  checkVolume(volume);
  checkWrittenBack(volume, files.folder());
}

}  // namespace ewa::fuzz

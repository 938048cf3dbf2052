// Loading fuzz inputs as volume files and checking what comes out.
#include "volume_checks.h"

#include <cmath>
#include <numeric>

#include <glm/matrix.hpp>

#include "core/splat_set.h"
#include "core/volume_orientation.h"
#include "core/transfer_function.h"
#include "fuzz_case.h"
#include "io/volume_loader.h"

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
}

}  // namespace ewa::fuzz

// Cutting a volume to a box: the index range of the centres inside, copied row by row.
#include "core/volume_crop.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace ewa {

std::optional<VoxelRange> voxelsInBox(const Volume& volume, const glm::dvec3& boxMin,
                                      const glm::dvec3& boxMax) {
  const auto& d = volume.dims();
  if (volume.empty()) return std::nullopt;
  // Index coordinates of the box's corners: (D^T (p - origin)) / spacing, D a rotation.
  const glm::dmat3 toIndex = glm::transpose(volume.direction());
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? boxMax.x : boxMin.x, (c & 2) ? boxMax.y : boxMin.y,
                            (c & 4) ? boxMax.z : boxMin.z);
    const glm::dvec3 index = toIndex * (corner - volume.origin()) / volume.spacing();
    lo = glm::min(lo, index);
    hi = glm::max(hi, index);
  }
  VoxelRange range;
  // A centre on the box's face counts as inside; a relative slack absorbs the rounding of the
  // corners' mapping (a box given at the centres themselves keeps them).
  constexpr double kSlack = 1e-9;
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(lo[a]) || !std::isfinite(hi[a])) return std::nullopt;
    const double first = std::ceil(lo[a] - kSlack * std::max(1.0, std::abs(lo[a])));
    const double last = std::floor(hi[a] + kSlack * std::max(1.0, std::abs(hi[a])));
    const double top = double(d[size_t(a)] - 1);
    if (last < 0.0 || first > top || first > last) return std::nullopt;
    range.low[size_t(a)] = int64_t(std::max(first, 0.0));
    range.high[size_t(a)] = int64_t(std::min(last, top));
  }
  return range;
}

Volume cropVolume(const Volume& volume, const VoxelRange& range) {
  const auto& d = volume.dims();
  for (size_t a = 0; a < 3; ++a)
    if (range.low[a] < 0 || range.high[a] >= d[a] || range.low[a] > range.high[a])
      throw std::invalid_argument("crop range outside the volume");
  const auto out = range.dims();
  const size_t bytesPerValue = scalarSize(volume.type());
  const size_t rowBytes = size_t(out[0]) * bytesPerValue;
  std::vector<uint8_t> bytes(rowBytes * size_t(out[1]) * size_t(out[2]));
  uint8_t* to = bytes.data();
  for (int64_t k = range.low[2]; k <= range.high[2]; ++k)
    for (int64_t j = range.low[1]; j <= range.high[1]; ++j, to += rowBytes)
      std::memcpy(to,
                  volume.bytes().data() + size_t(volume.index(range.low[0], j, k)) * bytesPerValue,
                  rowBytes);
  const glm::dvec3 origin =
      volume.worldPosition(double(range.low[0]), double(range.low[1]), double(range.low[2]));
  Volume cropped(out, volume.spacing(), origin, volume.type(), std::move(bytes));
  cropped.setDirection(volume.direction(), volume.patientFrame());
  cropped.setUnit(volume.unit());
  for (const std::string& note : volume.notes()) cropped.addNote(note);
  cropped.addNote("cropped to voxels " + std::to_string(range.low[0]) + "-" +
                  std::to_string(range.high[0]) + ", " + std::to_string(range.low[1]) + "-" +
                  std::to_string(range.high[1]) + ", " + std::to_string(range.low[2]) + "-" +
                  std::to_string(range.high[2]) + " of " + std::to_string(d[0]) + " x " +
                  std::to_string(d[1]) + " x " + std::to_string(d[2]));
  return cropped;
}

}  // namespace ewa

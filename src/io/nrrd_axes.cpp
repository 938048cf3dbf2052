// 4D NRRD: the non-spatial axis chosen from space directions or kinds, one volume cut out.
#include "io/nrrd_axes.h"

#include <cstring>

#include "io/file_scalar.h"
#include "io/load_failure.h"

namespace ewa {

NrrdExtraAxis pickNrrdExtraAxis(const std::string& path, const std::vector<int64_t>& sizes,
                                const std::vector<std::vector<double>>& directions,
                                const std::vector<std::string>& kinds) {
  std::vector<int> candidates;
  if (!directions.empty()) {
    for (int a = 0; a < 4; ++a)
      if (directions[size_t(a)].empty()) candidates.push_back(a);  // "none"
  } else if (!kinds.empty()) {
    for (int a = 0; a < 4; ++a)
      if (kinds[size_t(a)] != "domain" && kinds[size_t(a)] != "space") candidates.push_back(a);
  } else {
    failLoad(path, "a 4D NRRD needs space directions or kinds saying which axis is not spatial");
  }
  if (candidates.size() != 1)
    failLoad(path,
             "a 4D NRRD needs exactly one axis that is not spatial (space direction "
             "\"none\", or a kind other than domain and space), not " +
                 std::to_string(candidates.size()));
  NrrdExtraAxis extra;
  extra.axis = candidates[0];
  if (extra.axis != 0 && extra.axis != 3)
    failLoad(path, "the non-spatial axis of a 4D NRRD must be the first or the last, not axis " +
                       std::to_string(extra.axis));
  extra.size = sizes[size_t(extra.axis)];
  extra.kind = kinds.empty() ? std::string() : kinds[size_t(extra.axis)];
  const std::string& k = extra.kind;
  extra.channels = (k.size() > 6 && k.compare(k.size() - 6, 6, "-color") == 0) ||
                   k.find("vector") != std::string::npos || k == "normal" || k == "3-normal";
  return extra;
}

std::vector<uint8_t> nrrdVolumeOf(const std::vector<uint8_t>& bytes, const NrrdExtraAxis& extra,
                                  int64_t index, uint64_t voxels, size_t elementSize) {
  std::vector<uint8_t> out(size_t(voxels) * elementSize);
  if (extra.axis == 3) {
    std::memcpy(out.data(), bytes.data() + size_t(index) * out.size(), out.size());
    return out;
  }
  copyInterleaved(bytes.data() + size_t(index) * elementSize, size_t(extra.size), elementSize,
                  size_t(voxels), out.data());
  return out;
}

}  // namespace ewa

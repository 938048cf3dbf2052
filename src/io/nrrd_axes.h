// 4D NRRD: which axis is not spatial (time, a list of gradients, colour), and one volume of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

struct NrrdExtraAxis {
  int axis = -1;          // 0 (fastest: colour, vectors) or 3 (slowest: time, lists); -1 in 3D
  int64_t size = 1;       // its number of samples
  std::string kind;       // its kind, lower case ("list", "rgb-color", ...); "" when not given
  bool channels = false;  // a colour or vector kind: --channel picks one, else --frame
};

// The one non-spatial axis of a 4D NRRD: the one whose space direction is "none", else the one
// whose kind is not "domain" or "space". Throws LoadError naming `path` when neither says, when
// several axes qualify, or when it is a middle axis.
NrrdExtraAxis pickNrrdExtraAxis(const std::string& path, const std::vector<int64_t>& sizes,
                                const std::vector<std::vector<double>>& directions,
                                const std::vector<std::string>& kinds);

// Volume `index` of the extra axis out of 4D data `bytes` (x fastest) of `voxels` 3D voxels of
// `elementSize` bytes: every `size`-th element from `index` when the axis is the first, else
// the index-th block.
std::vector<uint8_t> nrrdVolumeOf(const std::vector<uint8_t>& bytes, const NrrdExtraAxis& extra,
                                  int64_t index, uint64_t voxels, size_t elementSize);

}  // namespace ewa

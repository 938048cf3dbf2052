// The planes the multi-dimensional TIFF tests write and check: 3 slices, 2 channels and 2 time
// points of 3 x 2 uint16 pixels, the plane (z, c, t) holding 1000 t + 100 c + 10 z + pixel.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/volume.h"

namespace ewa::testing {

constexpr int kPlaneSizes[3] = {3, 2, 2};  // z, c, t

// Plane `p` of `order` (fastest first: "ZCT", "CZT", ...) as z, c, t.
inline std::array<int, 3> zctOf(const std::string& order, int p) {
  std::array<int, 3> index{0, 0, 0};
  for (char d : order) {
    const int slot = d == 'Z' ? 0 : d == 'C' ? 1 : 2;
    index[size_t(slot)] = p % kPlaneSizes[slot];
    p /= kPlaneSizes[slot];
  }
  return index;
}

// Planes `from` to `to` - 1 of `order`, as pages (all 12 by default).
inline std::vector<std::vector<uint16_t>> planeRange(const std::string& order, int from = 0,
                                                     int to = 12) {
  std::vector<std::vector<uint16_t>> pages;
  for (int p = from; p < to; ++p) {
    const auto [z, c, t] = zctOf(order, p);
    std::vector<uint16_t> page(6);
    for (int i = 0; i < 6; ++i) page[size_t(i)] = uint16_t(1000 * t + 100 * c + 10 * z + i);
    pages.push_back(page);
  }
  return pages;
}

// `v` is the 3 slices of `channel` at time point `frame`.
inline void expectPlanes(const Volume& v, int channel, int frame) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{3, 2, 3}));
  for (int z = 0; z < 3; ++z)
    for (int i = 0; i < 6; ++i)
      ASSERT_EQ(v.valueAt(6 * z + i), 1000 * frame + 100 * channel + 10 * z + i)
          << "channel " << channel << " frame " << frame << " slice " << z << " pixel " << i;
}

}  // namespace ewa::testing

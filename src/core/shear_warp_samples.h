// Shared by the parallel and perspective compositing loops: the under operator, Lacroute's
// opaque-pixel links and the pre-integration pair table lookup.
#pragma once

#include <algorithm>
#include <cstdint>
#include <glm/vec4.hpp>

namespace ewa {

inline void under(glm::vec4& pixel, const glm::vec4& sample) {
  pixel += (1.0f - pixel.a) * sample;
}

// Lacroute's opaque-pixel links for one intermediate row: next[u] == u while pixel u may
// still change; once it is opaque, next[u] points further right. find() follows the links
// (halving the paths it walks), so runs of terminated rays cost almost nothing.
struct OpaqueLinks {
  int32_t* next;
  int find(int u) const {
    while (next[u] != u) {
      next[u] = next[next[u]];
      u = next[u];
    }
    return u;
  }
  void terminate(int u) const { next[u] = u + 1; }
};

// The pair table is diagonal-major: entry (f, b) at (b - f + n - 1) * n + f. The entry nearest
// (front, back):
inline int nearestPair(int n, float front, float back) {
  const int f = int(front + 0.5f), b = int(back + 0.5f);
  return (b - f + n - 1) * n + f;
}

template <bool kBilinear>
glm::vec4 lookupPair(const glm::vec4* table, int n, float front, float back) {
  if (!kBilinear) return table[nearestPair(n, front, back)];
  const int f0 = std::min(int(front), n - 2), b0 = std::min(int(back), n - 2);
  const float wf = front - f0, wb = back - b0;
  const glm::vec4* d0 = table + (b0 - f0 + n - 1) * n + f0;  // (f0, b0); (f0+1, b0+1) follows
  const glm::vec4* up = d0 + n;                              // (f0, b0 + 1)
  const glm::vec4* down = d0 - n + 1;                        // (f0 + 1, b0)
  return (d0[0] * (1.0f - wb) + up[0] * wb) * (1.0f - wf) +
         (down[0] * (1.0f - wb) + d0[1] * wb) * wf;
}

}  // namespace ewa

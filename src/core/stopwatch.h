// millisecondsSince: wall time from a steady-clock reading, for stage timings and budgets.
#pragma once

#include <chrono>

namespace ewa {

// Milliseconds of std::chrono::steady_clock since `start`.
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace ewa

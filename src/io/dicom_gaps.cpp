// Slices missing from a DICOM series: whole multiples of the step, filled by interpolation.
#include "io/dicom_gaps.h"

#include <algorithm>
#include <cmath>

namespace ewa {

std::vector<int64_t> missingSlicesAfter(const std::vector<double>& steps, size_t stored) {
  if (steps.empty()) return {};
  const double unit = *std::min_element(steps.begin(), steps.end());
  if (!(unit > 0.0)) return {};
  std::vector<int64_t> after;
  size_t ones = 0;
  int64_t missing = 0;
  for (double step : steps) {
    const double multiple = std::round(step / unit);
    // A run past the cap, or a step that is no whole multiple of the unit: not a gap to fill.
    if (multiple > double(kMaxMissingRun + 1) || std::fabs(step - multiple * unit) > 0.01 * unit)
      return {};
    ones += multiple == 1.0;
    after.push_back(int64_t(multiple) - 1);
    missing += after.back();
  }
  if (missing == 0 || 2 * ones < steps.size() || size_t(missing) > stored) return {};
  return after;
}

void fillMissingSlices(std::vector<double>& values, size_t plane,
                       const std::vector<int64_t>& missingAfter, bool integral) {
  int64_t missing = 0;
  for (int64_t m : missingAfter) missing += m;
  std::vector<double> filled;
  filled.reserve(values.size() + size_t(missing) * plane);
  for (size_t i = 0; i <= missingAfter.size(); ++i) {
    const auto a = values.begin() + ptrdiff_t(i * plane);
    filled.insert(filled.end(), a, a + ptrdiff_t(plane));
    if (i == missingAfter.size()) break;
    const auto b = a + ptrdiff_t(plane);
    const int64_t m = missingAfter[i];
    for (int64_t t = 1; t <= m; ++t) {
      const double w = double(t) / double(m + 1);  // the place between the two stored planes
      for (size_t p = 0; p < plane; ++p) {
        const double v = (1.0 - w) * a[ptrdiff_t(p)] + w * b[ptrdiff_t(p)];
        filled.push_back(integral ? std::round(v) : v);
      }
    }
  }
  values.swap(filled);
}

}  // namespace ewa

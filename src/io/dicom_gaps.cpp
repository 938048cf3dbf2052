// Slices of a DICOM series at uneven places: missing ones filled in, or the stack resampled.
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

std::vector<PlaneMix> planesWithMissing(const std::vector<int64_t>& missingAfter) {
  std::vector<PlaneMix> mix;
  for (size_t i = 0; i < missingAfter.size(); ++i) {
    mix.push_back({i, 0.0});
    const int64_t m = missingAfter[i];
    for (int64_t t = 1; t <= m; ++t) mix.push_back({i, double(t) / double(m + 1)});
  }
  mix.push_back({missingAfter.size(), 0.0});
  return mix;
}

std::vector<PlaneMix> regularPlanes(const std::vector<double>& at) {
  if (at.size() < 2) return {};
  std::vector<double> steps;
  for (size_t i = 1; i < at.size(); ++i) steps.push_back(at[i] - at[i - 1]);
  std::sort(steps.begin(), steps.end());
  const double median = steps[steps.size() / 2], span = at.back() - at.front();
  // Positions far past any scanner's (a fuzzed file's) may overflow: left as they are.
  if (!(median > 0.0) || !(span > 0.0) || !std::isfinite(span / median)) return {};
  const double most = double(kMaxResampleFactor * at.size());
  const size_t count = size_t(std::clamp(std::round(span / median) + 1.0, 2.0, most));
  std::vector<PlaneMix> mix;
  size_t below = 0;
  for (size_t k = 0; k < count; ++k) {
    const double z = at.front() + span * double(k) / double(count - 1);
    while (below + 2 < at.size() && at[below + 1] <= z) ++below;
    const double w = (z - at[below]) / (at[below + 1] - at[below]);
    mix.push_back({below, std::clamp(w, 0.0, 1.0)});
  }
  return mix;
}

void mixPlanes(std::vector<double>& values, size_t plane, const std::vector<PlaneMix>& mix,
               bool integral) {
  std::vector<double> out;
  out.reserve(mix.size() * plane);
  for (const PlaneMix& m : mix) {
    const auto a = values.begin() + ptrdiff_t(m.below * plane);
    if (m.weight == 0.0) {
      out.insert(out.end(), a, a + ptrdiff_t(plane));  // a stored plane, as it was
      continue;
    }
    const auto b = a + ptrdiff_t(plane);
    for (size_t p = 0; p < plane; ++p) {
      const double v = (1.0 - m.weight) * a[ptrdiff_t(p)] + m.weight * b[ptrdiff_t(p)];
      out.push_back(integral ? std::round(v) : v);
    }
  }
  values.swap(out);
}

}  // namespace ewa

// Slices missing from a DICOM series: found from the steps between positions, filled in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ewa {

// Steps between sorted slice positions (along the normal) that are whole multiples of the
// series' step: the shortest, which at least half the steps must be, each within 1%. Returns the
// number of slices missing after each stored one (steps.size() entries), or an empty vector when
// the steps are not such multiples, none is missing, more are missing than `stored` (a series
// that is mostly gap is not filled in) or a step spans more than kMaxMissingRun slices.
std::vector<int64_t> missingSlicesAfter(const std::vector<double>& steps, size_t stored);
constexpr int64_t kMaxMissingRun = 64;

// Puts the missing planes into `values` (`missingAfter.size() + 1` planes of `plane` values in
// order): each linear between the planes either side, by its place between them; rounded to
// whole numbers when `integral`.
void fillMissingSlices(std::vector<double>& values, size_t plane,
                       const std::vector<int64_t>& missingAfter, bool integral);

}  // namespace ewa

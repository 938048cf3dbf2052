// Slices of a DICOM series at uneven places: missing ones found from the steps between positions
// and filled in, or the stack resampled onto regular steps.
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

// One plane of a regular stack: (1 - weight) of stored plane `below` plus `weight` of the next.
struct PlaneMix {
  size_t below = 0;
  double weight = 0.0;
};

// The stored planes and, after each, its missing ones (missingSlicesAfter), each by its place
// between the stored planes either side.
std::vector<PlaneMix> planesWithMissing(const std::vector<int64_t>& missingAfter);

// Planes at sorted, unevenly spaced positions `at` (along the normal) resampled onto regular
// steps from the first to the last: about the median step apart (a whole number of steps spans
// them), at most kMaxResampleFactor times as many planes as stored, each linear between the
// stored planes either side.
std::vector<PlaneMix> regularPlanes(const std::vector<double>& at);
constexpr size_t kMaxResampleFactor = 2;
// Uneven stacks are resampled only when drawing them evenly spaced would move a slice further
// than this many steps from its place.
constexpr double kMaxMisplacedSlice = 0.1;

// `values` (planes of `plane` values, in the stored order) made the planes `mix` describes;
// rounded to whole numbers when `integral`.
void mixPlanes(std::vector<double>& values, size_t plane, const std::vector<PlaneMix>& mix,
               bool integral);

}  // namespace ewa

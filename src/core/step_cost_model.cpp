// StepCostModel: prices of entries, slab finishes and opacity checks from measured chunks.
#include "core/step_cost_model.h"

#include <algorithm>
#include <cmath>

namespace ewa {

namespace {

double blend(double old, double now) {
  return old > 0.0 && now < old ? 0.5 * (old + now) : now;
}

}  // namespace

void StepCostModel::update(double ms, size_t entries, size_t finishes, size_t checks) {
  if (!std::isfinite(ms) || ms < 0.0) return;
  checks = std::min(checks, finishes);
  if (finishes == 0 || msPerEntry_ <= 0.0) {
    // Without a known price an entry, the whole time is charged to the entries (safe: high).
    msPerEntry_ = blend(msPerEntry_, ms / double(std::max<size_t>(entries, 1)));
    return;
  }
  const double rest = std::max(0.0, ms - msPerEntry_ * double(entries));
  if (checks == 0 || msPerFinish_ <= 0.0) {
    // Before a plain finish is known, the checks' share is charged to the finishes (high).
    msPerFinish_ = blend(msPerFinish_, rest / double(finishes));
    return;
  }
  const double checkShare = std::max(0.0, rest - msPerFinish_ * double(finishes));
  msPerCheck_ = blend(msPerCheck_, checkShare / double(checks));
}

}  // namespace ewa

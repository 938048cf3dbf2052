// TwoWayTuner: try both ways, keep the cheaper, retry the other now and then.
#include "core/two_way_tuner.h"

#include <cmath>

namespace ewa {

int TwoWayTuner::choice() const {
  if (cost_[0] < 0.0) return 0;
  if (cost_[1] < 0.0) return 1;
  return sinceRetry_ >= kRetryEvery ? 1 - cheaper() : cheaper();
}

void TwoWayTuner::report(int way, double cost) {
  if (!std::isfinite(cost) || cost < 0.0) return;
  way &= 1;
  const bool measured = cost_[0] >= 0.0 && cost_[1] >= 0.0;
  if (measured && way != cheaper())
    sinceRetry_ = 0;  // the other way, retried
  else if (measured)
    ++sinceRetry_;
  cost_[way] = cost;
}

void TwoWayTuner::reset() {
  cost_[0] = cost_[1] = -1.0;
  sinceRetry_ = 0;
}

}  // namespace ewa

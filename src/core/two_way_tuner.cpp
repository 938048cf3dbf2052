// TwoWayTuner: try both ways, keep the cheaper, retry the other now and then.
#include "core/two_way_tuner.h"

#include <algorithm>
#include <cmath>

namespace ewa {

int TwoWayTuner::choice() const {
  if (cost_[first_] < 0.0) return first_;
  if (cost_[1 - first_] < 0.0) return 1 - first_;
  return sinceRetry_ >= retryEvery() ? 1 - cheaper() : cheaper();
}

int TwoWayTuner::retryEvery() const {
  const double cheap = cost_[cheaper()], dear = cost_[1 - cheaper()];
  if (!(cheap > 0.0) || !(dear > 0.0)) return kRetryEvery;
  // A retry of a way r times dearer costs r - 1 frames of the cheaper way more than a frame of
  // it: kRetryEvery * (r - 1) frames between retries keep them to 1/kRetryEvery of the time.
  return int(std::clamp(double(kRetryEvery) * (dear / cheap - 1.0), double(kRetryEvery),
                        double(kMaxRetryEvery)));
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

// Chooses the cheaper of two ways of drawing that give the same picture, from frames timed each
// way.
#pragma once

namespace ewa {

// Each way is tried once, then the cheaper one taken, and the other tried again now and then:
// their costs move with the view, the volume and the window's size. A way r times dearer is
// retried after kRetryEvery * (r - 1) frames of the cheaper (at least kRetryEvery, at most
// kMaxRetryEvery), so retries take at most about 1/kRetryEvery of the time whether the ways
// differ by a fifth (slab passes) or tenfold (compute tiles against the rasterizer on a GPU;
// there the cap leaves them 1/28). Costs are per unit of work (milliseconds a slab entry), so
// frames of different views compare.
class TwoWayTuner {
 public:
  static constexpr int kRetryEvery = 32;
  static constexpr int kMaxRetryEvery = 256;

  // `first`: the way tried first (0 or 1), the other second.
  explicit TwoWayTuner(int first = 0) : first_(first & 1) {}

  // The way (0 or 1) the next timed frame should take.
  int choice() const;
  // A frame drawn `way` took `cost` per unit of work; non-finite or negative costs are ignored.
  void report(int way, double cost);
  // Forgets both costs (SplatRenderer: a new volume): each way is tried again.
  void reset();
  // The latest cost of `way`; negative while it has not been measured.
  double cost(int way) const { return cost_[way & 1]; }
  // Frames of the cheaper way between retries of the other, from the costs measured.
  int retryEvery() const;

 private:
  int cheaper() const { return cost_[1] < cost_[0] ? 1 : 0; }

  double cost_[2] = {-1.0, -1.0};
  int first_ = 0;
  int sinceRetry_ = 0;  // frames the cheaper way has drawn since the other was last tried
};

}  // namespace ewa

// StepCostModel: what a budgeted step's slab work is expected to cost, learnt from the chunks
// it drew (the window's progressive refinement).
#pragma once

#include <cstddef>

namespace ewa {

// Three measured prices: a splat entry drawn, a slab finished (its images cleared, its
// composite pass over its rectangle), and the opacity check every few slabs adds to a finish
// (marks, termination query, occlusion pyramid). On llvmpipe at 1024x768 a finish costs more
// than a UI frame's whole budget, so it is priced on its own and planned as a unit: a step
// whose budget the entries have spent leaves the slab's finish to the next step.
class StepCostModel {
 public:
  // Whether anything has been measured (before that, steps draw fixed small chunks).
  bool measured() const { return msPerEntry_ > 0.0; }
  double msPerEntry() const { return msPerEntry_; }
  // A slab's finish, with or without the opacity check.
  double finishMs(bool check) const { return msPerFinish_ + (check ? msPerCheck_ : 0.0); }
  // A whole slab of `entries` entries and its finish.
  double slabMs(size_t entries, bool check) const {
    return msPerEntry_ * double(entries) + finishMs(check);
  }
  // A chunk of `entries` entries and `finishes` finishes (`checks` of them with the check)
  // took `ms`. Prices go up at once and down slowly: an overestimate costs a little speed, an
  // underestimate a stalled window. Non-finite or negative times are ignored.
  void update(double ms, size_t entries, size_t finishes, size_t checks);

 private:
  double msPerEntry_ = 0.0;
  double msPerFinish_ = 0.0;
  double msPerCheck_ = 0.0;
};

}  // namespace ewa

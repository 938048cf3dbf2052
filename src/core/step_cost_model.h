// StepCostModel: what a budgeted step's slab work is expected to cost, learnt from the chunks
// it drew (the window's progressive refinement).
#pragma once

#include <cstddef>

namespace ewa {

// Four measured prices: a splat entry drawn, a slab begun (its images cleared), a pixel of a
// slab's composite pass (its coarse marks carried over, its image blended under the picture),
// and the opacity check every few slabs adds to a slab's finish (marks, termination query,
// occlusion pyramid). On llvmpipe at 1024x768 one slab's pass can cost more than a UI frame's
// whole budget, so the pass is priced by the pixel and drawn in bands of rows where it must;
// a slab's clears cost as much as thousands of its entries.
class StepCostModel {
 public:
  // Whether anything has been measured (before that, steps draw fixed small chunks).
  bool measured() const { return msPerEntry_ > 0.0; }
  double msPerEntry() const { return msPerEntry_; }
  double msPerPixel() const { return msPerPixel_; }
  double beginMs() const { return msPerBegin_; }
  double checkMs() const { return msPerCheck_; }
  // A slab's finish: its pass over `pixels` pixels, with or without the opacity check.
  double finishMs(long long pixels, bool check) const {
    return msPerPixel_ * double(pixels) + (check ? msPerCheck_ : 0.0);
  }
  // A whole slab: begun, `entries` entries, its finish.
  double slabMs(size_t entries, long long pixels, bool check) const {
    return msPerBegin_ + msPerEntry_ * double(entries) + finishMs(pixels, check);
  }
  // What a chunk drew and how long it took.
  struct Chunk {
    double ms = 0.0;
    size_t entries = 0;
    long long pixels = 0;  // of slab passes
    size_t checks = 0;
    size_t begins = 0;  // slabs begun
  };
  // Learns from a chunk: a price no chunk has shown yet takes what the known ones leave of its
  // time (the first unknown present: charged high); known prices are scaled alike by what the
  // chunk took over what they predicted. Prices go up at once and down by halves: an
  // overestimate costs a little speed, an underestimate a stalled window. Non-finite or
  // negative times and empty chunks are ignored.
  void update(const Chunk& chunk);

 private:
  double msPerEntry_ = 0.0;
  double msPerPixel_ = 0.0;
  double msPerBegin_ = 0.0;
  double msPerCheck_ = 0.0;
};

// Rows of a slab's pass a step draws next: all `rowsLeft` where they fit in `roomMs` at `rowMs`
// a row; else whole multiples of `bandRows` that fit, at least `minRows` where this is the
// step's first work (a step always draws something) and none where fewer than `minRows` fit;
// never leaving fewer than `minRows` for a step of their own.
int passRowsToDraw(int rowsLeft, double rowMs, double roomMs, bool firstWork, int bandRows,
                   int minRows);

}  // namespace ewa

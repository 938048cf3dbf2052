// ProgressiveRefinement: starts, steps and times the window's progressive full-quality frame.
#include "ui/progressive_refinement.h"

#include <algorithm>

#include "core/stopwatch.h"

namespace ewa {

namespace {
// The least renderer time a UI frame gives the refinement: below it the fixed cost per step
// (GL state, the wait for the chunk) would dominate.
constexpr double kMinBudgetMs = 4.0;

}  // namespace

ProgressiveRefinement::ProgressiveRefinement(double budgetMs, double frameTargetMs)
    : maxBudgetMs_(std::max(budgetMs, 0.001)),
      frameTargetMs_(frameTargetMs),
      lastBudgetMs_(maxBudgetMs_) {}

double ProgressiveRefinement::budgetMs(bool presents) const {
  return std::clamp(frameTargetMs_ - otherMs_[presents ? 1 : 0],
                    std::min(kMinBudgetMs, maxBudgetMs_), maxBudgetMs_);
}

void ProgressiveRefinement::start(LodRenderer& lod, const Camera& camera,
                                  const RenderSettings& settings, glm::ivec2 size) {
  started_ = Clock::now();
  current_ = RefinementReport{};
  const Clock::time_point begin = Clock::now();
  lod.beginFull(camera, settings, size.x, size.y);
  current_.workMs = lastStepMs_ = millisecondsSince(begin);
  active_ = true;
  finishedThisFrame_ = false;
}

bool ProgressiveRefinement::step(LodRenderer& lod, bool presents) {
  if (!active_) return false;
  const Clock::time_point begin = Clock::now();
  lastBudgetMs_ = budgetMs(presents);
  steppedThisFrame_ = true;
  stepPresents_ = presents;
  const bool done = lod.stepFull(lastBudgetMs_);
  lastStepMs_ = millisecondsSince(begin);
  current_.workMs += lastStepMs_;
  ++current_.frames;
  if (!done) return false;
  active_ = false;
  finishedThisFrame_ = true;
  current_.wallMs = millisecondsSince(started_);
  current_.index = last_.index + 1;
  last_ = current_;
  return true;
}

bool ProgressiveRefinement::presentsStep(bool activity) const {
  if (!active_ || activity) return true;
  if (steppedThisFrame_) return stepPresents_;
  return millisecondsSince(lastPresent_) >= kPresentIntervalMs;
}

void ProgressiveRefinement::reportFrame(double ms) {
  const bool presented = presentedThisFrame_;
  presentedThisFrame_ = false;
  steppedThisFrame_ = false;
  if (!active_ && !finishedThisFrame_) return;
  current_.worstFrameMs = std::max(current_.worstFrameMs, ms);
  if (finishedThisFrame_) {
    // The frame that shows the finished picture ends the wall time too.
    last_.worstFrameMs = current_.worstFrameMs;
    finishedThisFrame_ = false;
  }
  // What the frame spent besides the step (events, panel, present, swap) leaves the rest of
  // the target to the next step of a frame of its kind.
  otherMs_[presented ? 1 : 0] = std::max(0.0, ms - lastStepMs_);
}

}  // namespace ewa

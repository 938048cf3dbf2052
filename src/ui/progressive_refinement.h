// ProgressiveRefinement: the window's full-quality frame drawn in chunks over several UI frames
// under a time budget, so the window keeps answering input while it refines.
#pragma once

#include <chrono>
#include <glm/vec2.hpp>

#include "render/lod_renderer.h"

namespace ewa {

// How the last finished refinement went (statistics panel, frame log).
struct RefinementReport {
  double wallMs = 0.0;        // from its start to the full picture on screen
  double workMs = 0.0;        // the steps' own time (GL work included: they wait for it)
  int frames = 0;             // UI frames it took
  double worstFrameMs = 0.0;  // the longest of those UI frames
  int index = 0;              // 1 for the first finished refinement, 2 for the next...
};

class ProgressiveRefinement {
 public:
  // `budgetMs`: the most renderer time a UI frame gives the refinement; `frameTargetMs`: the
  // UI frame time to stay under meanwhile (the budget shrinks when the rest of the frame,
  // panel and swap, leaves less; measured apart for frames that present and frames that do
  // not, since a present costs several times what the rest does).
  explicit ProgressiveRefinement(double budgetMs = 30.0, double frameTargetMs = 60.0);

  // Starts the full frame of this view (abandoning one under way).
  void start(LodRenderer& lod, const Camera& camera, const RenderSettings& settings,
             glm::ivec2 size);
  // Abandons the frame under way: the view, the size or a setting changed.
  void cancel() { active_ = false; }
  bool active() const { return active_; }
  // Draws this UI frame's share; true when the full picture is done (lod.last() is it).
  // `presents`: the frame will present (presentsStep), so its step gets what the target
  // leaves beside a presenting frame's other work.
  bool step(LodRenderer& lod, bool presents = false);
  // The UI frame that ran the last step took `ms` in all (only frames with a step count; one
  // that called notePresented counts as presenting).
  void reportFrame(double ms);
  // The share drawn of the frame under way (0..1).
  double progress(const LodRenderer& lod) const { return active_ ? lod.fullProgress() : 1.0; }
  // The budget of a step in a frame that presents or not; the last step's.
  double budgetMs(bool presents) const;
  double budgetMs() const { return lastBudgetMs_; }
  // How long the last start or step took (the rest of its UI frame is events, panel, swap).
  double lastStepMs() const { return lastStepMs_; }
  // The last finished refinement; frames == 0 before the first.
  const RefinementReport& last() const { return last_; }

  // Whether a UI frame whose work was an unfinished step presents: the picture on screen stays
  // the coarse one until the last step, so drawing it again (the image, the panels and the swap,
  // on llvmpipe a large share of such a frame and of the time to full quality) is needed only
  // after `activity` (input, new splats) and every kPresentIntervalMs for the progress bar.
  // Once a frame's step has run, that step's own answer holds to the frame's end: a step given
  // the budget of a frame that does not present must not present when the interval passes
  // during it (in a large window a present can cost more than the step itself, so such a frame
  // would overrun its target).
  bool presentsStep(bool activity) const;
  // The frame was presented (any frame: the interval counts from it).
  void notePresented() {
    lastPresent_ = Clock::now();
    presentedThisFrame_ = true;
  }
  // Four times a second: often enough for the progress bar, rarely enough that the presents add
  // little to the time to full quality (docs/performance.md, "Progressive refinement").
  static constexpr double kPresentIntervalMs = 250.0;

 private:
  using Clock = std::chrono::steady_clock;

  double maxBudgetMs_;
  double frameTargetMs_;
  // What the last UI frame of each kind (0: no present, 1: presents) spent besides its step.
  double otherMs_[2] = {0.0, 0.0};
  double lastBudgetMs_;
  bool presentedThisFrame_ = false;
  bool steppedThisFrame_ = false;  // step() ran in this UI frame (until reportFrame)
  bool stepPresents_ = false;      // and was told its frame presents
  bool active_ = false;
  bool finishedThisFrame_ = false;  // the last step finished: its frame completes the report
  double lastStepMs_ = 0.0;
  Clock::time_point started_;
  Clock::time_point lastPresent_ = Clock::now();
  RefinementReport current_;
  RefinementReport last_;
};

}  // namespace ewa

// SplatRenderer's budgeted steps: slabs drawn in timed chunks sized by a measured cost per
// splat entry (the window's refinement), and the whole-volume passes (X-ray, MIP).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

#include "core/stopwatch.h"
#include "render/splat_renderer.h"

namespace ewa {

namespace {
// A pass's bands: whole multiples of kBandRows rows (llvmpipe rasterizes its 64-pixel tiles in
// 16-pixel blocks), and at least kMinBandRows (a band has a fixed cost: state, a draw).
constexpr int kBandRows = 16, kMinBandRows = 32;
}  // namespace

bool SplatRenderer::drawSlabChunks(double budgetMs, Clock::time_point start) {
  // Cost model (stepCost_), measured per chunk: a price per splat entry drawn, per slab begun
  // (its clears), per pixel of a slab's composite pass and per opacity check (marks and
  // termination test, every few slabs). A chunk holds whole slabs while they fit; a slab too costly
  // for the time left is drawn in ranges of entries over several steps (its sums are
  // order-independent, so the picture is the same), and its finish, a pass over the slab's
  // rectangle that on llvmpipe can cost more than a UI frame's whole budget, in bands of rows (each
  // pixel's pass is its own) over as many steps as it needs. Entries drawn before anything is
  // measured, and the fewest a range holds; both fewer where the largest footprints are huge (a
  // small volume filling the window: a few of its splats cost as much as thousands of an ordinary
  // view's).
  constexpr double kFirstFragments = 2.0e6;
  const size_t kFirstChunk =
      size_t(std::clamp(kFirstFragments / frame_.fragmentsPerEntry, 1.0, 2048.0));
  const size_t kMinRange = std::min<size_t>(512, kFirstChunk);
  constexpr size_t kFirstSlabEnds = 1;  // slabs finished before anything is measured
  const size_t n = frame_.slabs.size();
  const bool unlimited = !std::isfinite(budgetMs);
  const auto finished = [&] { return frame_.nextSlab >= n || frame_.terminated; };
  setSlabLoopState();
  bool stepDrew = false;  // a step's first work is drawn even if it does not fit
  while (!finished()) {
    // Milliseconds this chunk may take, and what it is expected to take so far.
    const double allowed = unlimited ? budgetMs : budgetMs - millisecondsSince(start);
    const bool measured = stepCost_.measured();
    const bool planned = measured && !unlimited;  // else whole slabs, finishes whole
    const auto chunkStart = Clock::now();
    size_t entries = 0, ends = 0, checks = 0, bands = 0, begins = 0;
    long long pixels = 0;
    double expected = 0.0;
    const auto firstWork = [&] { return !stepDrew && entries + bands + ends == 0; };
    const auto begin = [&](size_t s) {
      beginCompositeSlab(s);
      ++begins;
      expected += stepCost_.beginMs();
    };
    const auto draw = [&](size_t s, size_t take) {
      drawSlabRange(s, frame_.nextEntry, take);
      frame_.nextEntry += take;
      entries += take;
      expected += stepCost_.msPerEntry() * double(take);
      frame_.drawnWeight += double(take);
    };
    // Rows [passRow, passRow + rows) of slab s's pass; after the last of them, its close (with
    // an opacity check that no longer fits, left to the next step's first work).
    const auto pass = [&](size_t s, int rows) {
      const PixelRect rect = slabPassRect(s);
      const int y1 = std::max(frame_.passRow, std::min(rect.y1, frame_.passRow + rows));
      const long long bandPixels =
          (long long)(y1 - frame_.passRow) * std::max(0, rect.x1 - rect.x0);
      // The finish weighs one mean slab's entries: the rows' share, the close one row's.
      const double weight = frame_.meanEntries / double(std::max(0, rect.y1 - rect.y0) + 1);
      if (y1 > frame_.passRow) {
        passSlabRows(s, frame_.passRow, y1);
        ++bands;
        pixels += bandPixels;
        expected += stepCost_.finishMs(bandPixels, false);
        frame_.drawnWeight += weight * double(y1 - frame_.passRow);
        frame_.passRow = y1;
      }
      if (frame_.passRow < rect.y1) return;
      const bool check = finishChecks(s);
      if (check && planned && !firstWork() && expected + stepCost_.checkMs() > allowed) return;
      closeSlab(s);
      ++ends;
      checks += check ? 1 : 0;
      expected += check ? stepCost_.checkMs() : 0.0;
      frame_.drawnWeight += weight;
      frame_.nextEntry = 0;
      frame_.finishPending = false;
      ++frame_.nextSlab;
    };
    const auto startFinish = [&](size_t s) {
      frame_.finishPending = true;
      frame_.passRow = std::max(0, slabPassRect(s).y0);
    };
    while (!finished() && (firstWork() || expected < allowed)) {
      const size_t s = frame_.nextSlab;
      const bool check = finishChecks(s);
      const PixelRect rect = slabPassRect(s);
      if (frame_.finishPending) {
        // As many rows as fit (the check with the last), in whole bands.
        const int rowsLeft = std::max(0, rect.y1 - frame_.passRow);
        int rows = rowsLeft;
        if (planned) {
          const double rowMs = stepCost_.msPerPixel() * double(std::max(0, rect.x1 - rect.x0));
          const double room = allowed - expected - (check ? stepCost_.checkMs() : 0.0);
          rows = passRowsToDraw(rowsLeft, rowMs, room, firstWork(), kBandRows, kMinBandRows);
          if (rowsLeft > 0 && rows == 0) break;
        }
        const size_t nextSlab = frame_.nextSlab;
        pass(s, rows);
        if (frame_.nextSlab == nextSlab && frame_.passRow >= rect.y1) break;  // check waits
        continue;
      }
      const size_t count = slabInOrder(s).count;
      const double wholeMs = stepCost_.slabMs(count, rect.area(), check);
      if (frame_.nextEntry == 0 &&
          (unlimited || (measured && expected + wholeMs <= allowed) ||
           (!measured && entries + count <= kFirstChunk && ends < kFirstSlabEnds))) {
        begin(s);
        draw(s, count);
        startFinish(s);
        pass(s, std::max(0, rect.y1 - frame_.passRow));
        continue;
      }
      const double left = double(count - frame_.nextEntry);
      const double least = std::min(double(kMinRange), left);
      const double beginMs = frame_.nextEntry == 0 ? stepCost_.beginMs() : 0.0;
      const double fit = measured ? (allowed - expected - beginMs) / stepCost_.msPerEntry()
                                  : double(kFirstChunk - entries);
      if (!firstWork() && fit < least) break;
      if (frame_.nextEntry == 0) begin(s);
      draw(s, size_t(std::clamp(fit, least, left)));
      if (frame_.nextEntry == count) {
        startFinish(s);
        // Before anything is measured, the whole finish: its price is learnt from this chunk.
        if (!measured) pass(s, std::max(0, rect.y1 - frame_.passRow));
      }
      if (!measured) break;  // one measurement before planning more
    }
    if (unlimited) continue;
    if (entries + bands + ends + begins == 0) break;  // nothing more fits this step
    stepDrew = true;
    // llvmpipe does the GL work by glFinish: the chunk's time is only known after it.
    glFinish();
    stepCost_.update({millisecondsSince(chunkStart), entries, pixels, checks, begins});
    if (millisecondsSince(start) >= budgetMs) break;
  }
  endConditionalSlabs();  // the window draws between steps, the final pass after the last
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
  return finished();
}

bool SplatRenderer::drawWholeVolumeChunks(double budgetMs, Clock::time_point start) {
  // X-ray and MIP: one pass over every splat with order-independent blending (sum or max),
  // so the splat list may be drawn in ranges, as many entries per step as the budget allows.
  const RenderSettings& settings = frame_.settings;
  const bool unlimited = !std::isfinite(budgetMs);
  Slab all = frame_.slabs.front();
  const bool window = depthWindow_ && settings.mode == RenderMode::XRay;
  if (window) {
    all.nearDepth = depthWindow_->first;
    all.farDepth = depthWindow_->second;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.slabFbo.id());
  glBlendFunc(GL_ONE, GL_ONE);
  if (settings.mode == RenderMode::Mip) glBlendEquation(GL_MAX);
  // Entries drawn before anything is measured, and the fewest a step draws (cheap anywhere).
  constexpr size_t kFirstChunk = 4096, kMinChunk = 1024;
  if (frame_.indirect) {  // the whole single slab, its count on the GPU (budget unlimited)
    setSlabUniforms(all, window, false, 0);
    drawSplats(all, stats_.quadPass, 0);
    frame_.nextEntry = all.count;
  }
  while (frame_.nextEntry < all.count) {
    size_t count = all.count - frame_.nextEntry;
    if (!unlimited) {
      const double left = budgetMs - millisecondsSince(start);
      const double fit = stepCost_.measured() ? left / stepCost_.msPerEntry() : double(kFirstChunk);
      count = size_t(std::clamp(fit, double(std::min(kMinChunk, count)), double(count)));
    }
    Slab range = all;
    range.first = all.first + uint32_t(frame_.nextEntry);
    range.count = count;
    const auto chunkStart = Clock::now();
    setSlabUniforms(range, window, false);
    drawSplats(range, stats_.quadPass);
    frame_.nextEntry += count;
    frame_.drawnWeight += double(count);
    if (unlimited) continue;
    glFinish();
    stepCost_.update({millisecondsSince(chunkStart), count, 0, 0, 0});
    if (millisecondsSince(start) + stepCost_.msPerEntry() * double(kMinChunk) > budgetMs) break;
  }
  glBlendEquation(GL_FUNC_ADD);
  stats_.slabsDrawn = 1;
  return frame_.indirect || frame_.nextEntry >= all.count;
}

bool SplatRenderer::stepFrame(double budgetMs) {
  if (!frame_.active) return true;
  const auto start = Clock::now();
  // A new size's images first: on a software GL each takes tens of ms, so a step makes what
  // its budget holds and the partition's worker goes on meanwhile.
  if (!prepareTargets(budgetMs)) {
    stats_.renderMs += millisecondsSince(start);
    return false;
  }
  if (frame_.partitionPending) {
    // A budgeted step waits for the worker at most its budget; the window keeps its picture
    // meanwhile. The upload and the first slabs then share what is left of the budget.
    const auto budget = std::chrono::duration<double, std::milli>(std::min(budgetMs, 1e9));
    if (std::isfinite(budgetMs) &&
        pendingPartition_.wait_for(budget) != std::future_status::ready) {
      stats_.renderMs += millisecondsSince(start);
      return false;
    }
    takeCpuPartition(std::isfinite(budgetMs));
  }
  if (frame_.orderUploading && !uploadOrderPieces(budgetMs, start)) {
    stats_.renderMs += millisecondsSince(start);
    return false;  // more of the order list next step
  }
  if (frame_.gradientsPending) {
    // Ray normals: the gradient texture, packed on a worker since beginFrame (or prepare). A
    // budgeted step waits for it at most what is left of its budget; the wait counts with
    // classification.
    const auto waitStart = Clock::now();
    const double left =
        std::isfinite(budgetMs) ? std::max(0.0, budgetMs - millisecondsSince(start)) : budgetMs;
    if (!gradients_.ready(left)) {
      stats_.renderMs += millisecondsSince(start);
      return false;
    }
    stats_.classifyMs += millisecondsSince(waitStart);
    frame_.gradientsPending = false;
  }
  const auto drawStart = Clock::now();  // the splat stage's time leaves the partition out
  // Drawing within a budget needs each slab's count: read the GPU's back (a short wait) before
  // anything is drawn.
  if (frame_.indirect && std::isfinite(budgetMs) && frame_.nextSlab == 0) takeGpuCounts();
  // A whole frame drawn in this one step may be timed on the GPU: no wait between its stages.
  frame_.timed = gpuTimers_ && !std::isfinite(budgetMs) && frame_.drawnWeight == 0.0;
  if (frame_.timed) glQueryCounter(timers_[0], GL_TIMESTAMP);
  // A whole composite frame in compute tiles, if asked for and they draw its settings (in a
  // budgeted step: auto's choice, drawn whole where it fits a UI frame).
  if (frame_.drawSplats && !frame_.slabsDone && tilesFitStep(budgetMs) &&
      tilesWanted(frame_.settings) && frame_.settings.mode == RenderMode::Composite &&
      frame_.nextSlab == 0 && drawTiles()) {
    frame_.drawSplats = false;
    stats_.splatMs += millisecondsSince(drawStart);  // the tiles wait for their passes
  }
  // A whole frame on the CPU, if wanted and it draws the frame's settings; within a budget
  // the steps wait for its worker.
  if (frame_.drawSplats && !frame_.slabsDone && cpuWanted(frame_.settings) &&
      frame_.nextSlab == 0) {
    const CpuStep step = drawCpu(budgetMs, start);
    if (step == CpuStep::Pending) {
      stats_.renderMs += millisecondsSince(start);
      return false;
    }
    if (step == CpuStep::Drawn) frame_.drawSplats = false;
  }
  bool drewSlabs = false;  // this step: the final pass may not fit beside them
  if (frame_.drawSplats && !frame_.slabsDone) {
    // Another renderer sharing the programs drew since this frame set them up.
    if (programs_->user != this) setFrameUniforms();
    bindFrameState();
    glEnable(GL_BLEND);
    const bool done = frame_.settings.mode == RenderMode::Composite
                          ? drawSlabChunks(budgetMs, start)
                          : drawWholeVolumeChunks(budgetMs, start);
    glDisable(GL_BLEND);
    if (!done) {
      // The window draws between steps: leave it the default framebuffer, as render() does.
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glUseProgram(0);
      stats_.splatMs += millisecondsSince(drawStart);
      stats_.renderMs += millisecondsSince(start);
      return false;
    }
    if (!frame_.timed) {
      // The slab loop's GPU work (splats and the blends between slabs) ends here; waiting for
      // it costs little, since the final pass below waits anyway.
      glFinish();
      stats_.splatMs += millisecondsSince(drawStart);
    }
    frame_.slabsDone = drewSlabs = true;
  }
  if (std::isfinite(budgetMs)) {
    // The final pass, over the whole picture (its cost grows with the pixels: on llvmpipe in a
    // large window past a step's budget), in bands of rows that fit what the step has left, over as
    // many steps as it needs (at least a band where it is a step's first work).
    bool drewFinal = false;
    while (frame_.finalRow < frame_.height) {
      const int rowsLeft = frame_.height - frame_.finalRow;
      const int rows = passRowsToDraw(rowsLeft, finalRowMs(), budgetMs - millisecondsSince(start),
                                      !drewSlabs && !drewFinal, kBandRows, kMinBandRows);
      if (rows == 0) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glUseProgram(0);
        stats_.renderMs += millisecondsSince(start);
        return false;
      }
      // A pass split over steps draws into an image not shown meanwhile.
      if (frame_.finalRow == 0 && rows < frame_.height) targets_.beginOutput();
      drawFinalPass(frame_.finalRow, frame_.finalRow + rows);
      frame_.finalRow += rows;
      frame_.drawnWeight += frame_.finalWeight * double(rows) / double(frame_.height);
      drewFinal = true;
    }
  } else {
    if (frame_.timed) glQueryCounter(timers_[1], GL_TIMESTAMP);
    drawFinalPass(0, frame_.height);
  }
  if (frame_.occlusion) stats_.entriesCulled = occlusion_.readCount();  // the GPU is idle
  if (frame_.indirect) {
    // Statistics only: the GPU is idle after the final pass, so reading the counts costs
    // little. Entries drawn: those of the slabs drawn before early termination.
    gpuPartition_->readCounts();
    size_t slabs = 0;
    for (const Slab& slab : gpuPartition_->slabs()) slabs += slab.count > 0;
    stats_.slabs = slabs;
    frame_.slabs = gpuPartition_->slabs();
    const bool composite = frame_.settings.mode == RenderMode::Composite;
    const size_t drawn = composite && !frame_.tiles ? frame_.nextSlab : frame_.slabs.size();
    for (size_t s = 0; s < drawn && s < frame_.slabs.size(); ++s)
      stats_.slabEntries += slabInOrder(s).count;
  }
  // Auto passes: this frame's splat stage a slab entry, for the way it took (the GPU
  // partition's entries are only counted above). A way's first frame in this renderer is not
  // counted: it pays once for what the driver makes on first use (counted, that cost could make
  // the faster way look dearer, and the slower one would be kept).
  if (frame_.quarters && !frame_.tiles) {
    const int way = frame_.slabPasses - 1;
    const bool firstUse = (passWaysDrawn_ & (1u << way)) == 0;
    passWaysDrawn_ |= 1u << way;
    if (frame_.timed && frame_.settings.slabPasses == 0 && stats_.slabEntries > 0 && !firstUse)
      passTuner_.report(way, stats_.splatMs / double(stats_.slabEntries));
  }
  reportSplatterCost();
  frame_.active = false;
  stats_.renderMs += millisecondsSince(start);
  return true;
}

double SplatRenderer::finalRowMs() const {
  // Before one is measured, a slab pass's price a pixel: it reads more than the final pass.
  return double(frame_.width) *
         (finalMsPerPixel_ > 0.0 ? finalMsPerPixel_ : stepCost_.msPerPixel());
}

double SplatRenderer::frameProgress() const {
  if (!frame_.active) return 1.0;
  return frame_.totalWeight > 0.0 ? std::min(1.0, frame_.drawnWeight / frame_.totalWeight) : 0.0;
}

}  // namespace ewa

// SplatRenderer's frame: the slab partition, the slab loop (front to back with early
// termination, or back to front) drawn in timed chunks, the X-ray and MIP passes, the final
// picture.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

#include "core/clip_share.h"
#include "core/kernel_reach.h"
#include "core/stopwatch.h"
#include "core/volume_orientation.h"
#include "gl/gl_error.h"
#include "render/splat_renderer.h"

namespace ewa {

namespace {

// Front to back, the opaque pixels are marked and counted after every this many slabs: often
// enough to stop soon after the picture is opaque, rarely enough to cost little.
constexpr size_t kCheckEvery = 4;

// World to clip space for the pixel mapping of `proj`: x_pixel = principal + f u.xy / depth
// (or ppu u.xy), and clip z inside [-w, w] for depths beyond `nearClip`.
glm::mat4 clipMatrix(const Projection& proj, const glm::dmat4& view, double nearClip) {
  glm::dmat4 p(0.0);
  const double w = proj.width, h = proj.height;
  const double ox = 2.0 * proj.principal.x / w - 1.0, oy = 2.0 * proj.principal.y / h - 1.0;
  if (proj.orthographic) {
    p[0][0] = 2.0 * proj.pixelsPerUnit / w;
    p[1][1] = 2.0 * proj.pixelsPerUnit / h;
    p[3][0] = ox;
    p[3][1] = oy;
    p[3][3] = 1.0;
  } else {
    p[0][0] = 2.0 * proj.focalPixels / w;
    p[1][1] = 2.0 * proj.focalPixels / h;
    p[2][0] = -ox;
    p[2][1] = -oy;
    p[2][2] = -1.0;
    p[3][2] = -2.0 * nearClip;
    p[2][3] = -1.0;
  }
  return glm::mat4(p * view);
}

}  // namespace

bool SplatRenderer::issueOpaqueQuery(unsigned query) {
  const Camera& camera = frame_.camera;
  const Projection& proj = frame_.proj;
  const glm::dvec3& sp = volume_->spacing();
  const double maxSpacing = std::max({sp.x, sp.y, sp.z});
  const KernelReach& reach = frame_.reach;
  const glm::dvec3 lo = volume_->boundsMin(), hi = volume_->boundsMax();
  const glm::dmat4 view = camera.viewMatrix();
  const DepthRange box = boxDepthRange(view, lo, hi);
  // A box reaching the eye plane would be clipped: not a safe bound for the test.
  if (!proj.orthographic &&
      box.nearest < 2.0 * std::max(maxSpacing, reach.maxSigma) * std::sqrt(reach.cutoff))
    return false;
  const double farDepth = std::max(0.0, box.farthest);
  // Grow the box by what a kernel reaches beyond its centre at the farthest corner (reach
  // grows with depth), plus a pixel for rasterization.
  const double grow = worldReach(reach, farDepth) + worldPerPixel(reach, farDepth);
  boxProgram_.setMat4("uClip", clipMatrix(proj, view, 0.5 * maxSpacing));
  boxProgram_.setVec3("uBoxMin", glm::vec3(lo - grow));
  boxProgram_.setVec3("uBoxMax", glm::vec3(hi + grow));
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.slabFbo.id());
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glUseProgram(boxProgram_.id());
  glDrawArrays(GL_TRIANGLES, 0, 36);
  glEndQuery(GL_SAMPLES_PASSED);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return true;
}

bool SplatRenderer::terminationCheck() {
  const int current = frame_.nextQuery, previous = current ^ 1;
  endConditionalSlabs();  // the check's own query counts unconditionally
  const bool issued = issueOpaqueQuery(queries_[current]);
  if (!laggedTermination_) {
    GLuint samples = 1;
    if (issued) glGetQueryObjectuiv(queries_[current], GL_QUERY_RESULT, &samples);
    return samples == 0;
  }
  bool done = false;
  if (frame_.queryIssued[previous]) {
    GLuint available = 0, samples = 1;
    glGetQueryObjectuiv(queries_[previous], GL_QUERY_RESULT_AVAILABLE, &available);
    if (available) {
      glGetQueryObjectuiv(queries_[previous], GL_QUERY_RESULT, &samples);
      frame_.queryIssued[previous] = false;
      done = samples == 0;
    }
  }
  if (frame_.queryIssued[previous] && !done) {
    // The CPU has no answer yet: until the next check the GPU draws only if the last check
    // counted an unmarked pixel. The GPU waits for that answer, a check's slabs back and so
    // all but certainly there, and never the CPU; the stencil rejects what would be hidden
    // anyway, so the picture is the same as without.
    glBeginConditionalRender(queries_[previous], GL_QUERY_WAIT);
    frame_.conditional = true;
  }
  frame_.queryIssued[current] = issued;
  frame_.nextQuery = previous;
  glFlush();  // so that the query's answer comes while the next slabs are drawn
  return done;
}

void SplatRenderer::endConditionalSlabs() {
  if (!frame_.conditional) return;
  glEndConditionalRender();
  frame_.conditional = false;
}

bool SplatRenderer::terminates() const {
  const RenderSettings& settings = frame_.settings;
  return settings.order == CompositeOrder::FrontToBack && settings.terminationOpacity < 1.0;
}

void SplatRenderer::setSlabLoopState() {
  const RenderSettings& settings = frame_.settings;
  const bool terminate = terminates();
  targets_.slabNormal.bindUnit(3);
  targets_.accum.bindUnit(2);
  markProgram_.setInt("uAccum", 2);
  markProgram_.setFloat("uThreshold", float(settings.terminationOpacity));
  if (terminate) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  }
}

size_t SplatRenderer::slabPosition(size_t s) const {
  const bool frontToBack = frame_.settings.order == CompositeOrder::FrontToBack;
  return frontToBack ? s : frame_.slabs.size() - 1 - s;
}

const Slab& SplatRenderer::slabInOrder(size_t s) const {
  return frame_.slabs[slabPosition(s)];
}

void SplatRenderer::computeSlabRects() {
  frame_.slabRects.clear();
  frame_.slabScales.clear();
  frame_.markRect = PixelRect{};
  if (!volume_ || frame_.settings.mode != RenderMode::Composite) return;
  const RenderSettings& settings = frame_.settings;
  const glm::dvec3& sp = volume_->spacing();
  const FootprintParams params = footprintParams(settings, sp);
  const KernelReach& reach = frame_.reach;
  // Surface splats sit up to one smallest spacing off their voxel along the normal.
  const glm::dvec3 margin(params.minSpacing);
  const glm::dmat4 view = frame_.camera.viewMatrix();
  for (const Slab& slab : frame_.slabs)
    frame_.slabRects.push_back(slabPixelRect(
        view, frame_.proj, reach, volume_->boundsMin() - margin, volume_->boundsMax() + margin,
        slab.nearDepth, slab.farDepth, params.cullDepth));
  // Coarser slab images where every kernel a slab lists is wide enough on screen. Never with
  // surface splats (flat: a footprint as thin as the low-pass filter seen edge on), nor for
  // shaded post-classification (its normals are derivatives of the slab's values, which the
  // bilinear read-back bends: up to 70 levels on engine's plates against a few unshaded), nor
  // for tiny pictures (a coarser image and its border must fit in the slab image).
  const bool coarse = settings.coarseSlabs && classified_.surfaceCount == 0 &&
                      !(postClassified(settings) && settings.lighting.enabled) &&
                      std::min(frame_.width, frame_.height) >= 16;
  const double boxFar =
      std::max(0.0, boxDepthRange(view, volume_->boundsMin(), volume_->boundsMax()).farthest);
  const double minSigma = settings.kernelWidth * params.minSpacing;
  for (const Slab& slab : frame_.slabs) {
    // A kernel listed in the slab lies at most its depth reach behind the far plane.
    const double reachFar = depthReach(reach, reach.maxSigma * reach.maxSigma, slab.farDepth);
    const double farthest = std::min(slab.farDepth + reachFar, boxFar);
    frame_.slabScales.push_back(coarse ? slabImageScale(reach, minSigma, farthest) : 1.0);
  }
}

double SplatRenderer::slabScale(size_t s) const {
  const size_t i = slabPosition(s);
  return i < frame_.slabScales.size() ? frame_.slabScales[i] : 1.0;
}

gl::Program& SplatRenderer::slabPassProgram(size_t s) {
  const bool scaled = slabScale(s) > 1 || (frame_.pairedSlabs && s > 0 && slabScale(s - 1) > 1);
  return *slabPass_[scaled && slabPass_[1] ? 1 : 0];
}

void SplatRenderer::scissorToSlab(size_t s, double scale) {
  if (!slabScissor_ || frame_.slabRects.size() != frame_.slabs.size()) return;
  scissorTo(scaledRect(frame_.slabRects[slabPosition(s)], scale));
}

void SplatRenderer::scissorTo(const PixelRect& r) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x0, r.y0, std::max(0, r.x1 - r.x0), std::max(0, r.y1 - r.y0));
}

float SplatRenderer::slabMarkStep() const {
  return float(2.0 / double(frame_.slabs.size() + 2));
}

float SplatRenderer::slabMark(size_t s) const {
  return float(-1.0 + double(s + 1) * slabMarkStep());
}

int SplatRenderer::slabImageOf(size_t s) const {
  return frame_.pairedSlabs ? int(s % 2) : 0;
}

void SplatRenderer::beginCompositeSlab(size_t s) {
  // Whole-image clears: llvmpipe clears a whole image by marking its tiles (scissored, it
  // writes every pixel: engine's frames took 6% longer), GPUs have fast clears too, and on
  // llvmpipe (Mesa 22.3) a scissored clear of the second buffer left old normal sums behind.
  // With paired slabs this also empties, outside this slab's rectangle, the image the next
  // slab reads as its neighbour's.
  const GLfloat zero[4] = {0, 0, 0, 0};
  gl::Framebuffer& target = targets_.slabTarget(slabImageOf(s));
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  target.clearColor(0, zero);
  if (voxelNormalSums(frame_.settings)) target.clearColor(1, zero);
  if (frame_.quarters) target.clearColor(2, zero);
  if (slabScale(s) > 1.0)
    glClearNamedFramebufferfi(targets_.slabCoarseTarget(slabImageOf(s)).id(), GL_DEPTH_STENCIL, 0,
                              0.0f, 0);
}

void SplatRenderer::drawSlabRange(size_t s, size_t first, size_t count) {
  Slab range = slabInOrder(s);
  range.first += uint32_t(first);
  range.count = count;
  const double scale = slabScale(s);
  scissorToSlab(s, scale);
  // Inside a slab: order-independent sums of each kernel's share of optical depth and light.
  // A coarser image is drawn into the lower left corner of its slab image, with the marks of
  // its own depth image.
  const bool coarser = scale > 1.0;
  const int image = slabImageOf(s);
  glBindFramebuffer(GL_FRAMEBUFFER,
                    (coarser ? targets_.slabCoarseTarget(image) : targets_.slabTarget(image)).id());
  glBlendFunc(GL_ONE, GL_ONE);
  const int gpuSlab = frame_.indirect ? int(slabPosition(s)) : -1;  // then a whole slab
  setSlabUniforms(range, true, true, gpuSlab);
  setSplatScale(scale);
  // Each splat fragment leaves the slab's mark in the depth buffer (written before the shader,
  // so a footprint's whole point or quad is marked), for its slab pass.
  for (gl::Program* p : splatPrograms_.both()) p->setFloat("uSlabMark", slabMark(s));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  // The stencil marks the picture's pixels: coarser images draw every texel (near slabs, where
  // little is opaque yet).
  if (coarser) glDisable(GL_STENCIL_TEST);
  if (frame_.quarters && frame_.slabPasses == 2) {
    // The front quarters (and the voxel normals) first, then the back quarters: the same sums,
    // each pass blending into one image.
    // Each pass leaves out the kernels whose cut depth profile misses its half (the front pass
    // only without voxel normals, whose sums take the whole slab): they add exactly nothing.
    gl::Framebuffer& fbo = coarser ? targets_.slabCoarseTarget(image) : targets_.slabTarget(image);
    const auto passHalf = [&](int half) {
      for (gl::Program* p : splatPrograms_.both())
        p->setInt("uPassHalf", passHalfCulling_ ? half : 0);
    };
    fbo.drawTo(0b011u);
    passHalf(targets_.normalSums() ? 0 : 1);
    drawSplats(range, stats_.quadPass, gpuSlab);
    const size_t entries = stats_.slabEntries;  // the second pass draws the same entries
    fbo.drawTo(0b100u);
    passHalf(2);
    drawSplats(range, stats_.quadPass, gpuSlab);
    passHalf(0);
    stats_.slabEntries = entries;
    fbo.drawTo(~0u);
  } else {
    drawSplats(range, stats_.quadPass, gpuSlab);
  }
  if (coarser && terminates()) glEnable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
}

void SplatRenderer::blitCoarseMarks(size_t s) {
  // Each picture pixel takes the texel its centre lies in (scaledCoordinate); the scissor
  // keeps the blit to the slab's rectangle.
  const BlitRects r = coarseToPictureBlit(frame_.width, frame_.height, slabScale(s));
  scissorToSlab(s);
  glBlitNamedFramebuffer(targets_.slabCoarseTarget(slabImageOf(s)).id(), targets_.accumFbo.id(),
                         r.source.x0, r.source.y0, r.source.x1, r.source.y1, r.destination.x0,
                         r.destination.y0, r.destination.x1, r.destination.y1, GL_DEPTH_BUFFER_BIT,
                         GL_NEAREST);
}

void SplatRenderer::endCompositeSlab(size_t s) {
  const RenderSettings& settings = frame_.settings;
  const bool frontToBack = settings.order == CompositeOrder::FrontToBack;
  const bool terminate = frontToBack && settings.terminationOpacity < 1.0;
  const size_t n = frame_.slabs.size();
  // Between slabs: 1 - exp(-depth) composited under (front to back) or over (back to front).
  if (slabScale(s) > 1.0) blitCoarseMarks(s);
  scissorToSlab(s);
  if (frame_.slabRects.size() == n)
    frame_.markRect = frame_.markRect.unite(frame_.slabRects[slabPosition(s)]);
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.accumFbo.id());
  if (frontToBack)
    glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  else
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  targets_.slabImage(slabImageOf(s)).bindUnit(1);
  if (frame_.quarters) targets_.slabBackImage(slabImageOf(s)).bindUnit(kSlabBackUnit);
  gl::Program& pass = slabPassProgram(s);
  pass.setFloat("uSlabScale", float(slabScale(s)));
  if (frame_.pairedSlabs) {
    // The slab drawn before this one, if it is this one's neighbour in depth (empty slabs are
    // not drawn): a segment runs from its nearer half's value to this slab's.
    targets_.slabImage(slabImageOf(s + 1)).bindUnit(kNeighbourSlabUnit);
    if (frame_.quarters) targets_.slabBackImage(slabImageOf(s + 1)).bindUnit(kNeighbourBackUnit);
    const bool adjacent = s > 0 && slabsAdjacent(slabInOrder(s - 1), slabInOrder(s));
    pass.setInt("uNeighbour", adjacent ? 1 : 0);
    pass.setFloat("uNeighbourScale", s > 0 ? float(slabScale(s - 1)) : 1.0f);
  }
  const Slab& slab = slabInOrder(s);
  pass.setVec2("uSlabDepths", glm::vec2(slab.nearDepth, slab.farDepth));
  // The pass runs only where the slab's splats left their mark (a coarser slab's carried over
  // by blitCoarseMarks): llvmpipe runs a shader's every line under a mask (discard saves
  // nothing), but skips blocks that fail an early depth test. The pass lies half a mark below
  // its slab's: earlier slabs' marks and the cleared 0 lie below it and fail GL_LEQUAL,
  // without an exact equality of depths.
  pass.setFloat("uSlabMark", slabMark(s) - 0.5f * slabMarkStep());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glUseProgram(pass.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);  // clears respect the mask
  ++stats_.slabsDrawn;
  if (slabScale(s) > 1) ++stats_.slabsCoarse;
  if (terminate && (s + 1) % kCheckEvery == 0 && s + 1 < n) {
    // Mark pixels that reached the threshold; later splat fragments there fail the stencil.
    // Only the slabs composited since the last marks changed the image: their rectangles.
    if (slabScissor_ && frame_.slabRects.size() == n) scissorTo(frame_.markRect);
    frame_.markRect = PixelRect{};
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.slabFbo.id());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glUseProgram(markProgram_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_SCISSOR_TEST);  // the bounding-box query below counts the whole image
    if (frame_.occlusion) {
      // The pyramid of the pixels just marked: later slabs' splats over them are culled.
      occlusion_.build(targets_.accum, float(settings.terminationOpacity));
      frame_.pyramidBuilt = true;
      for (gl::Program* p : splatPrograms_.both())
        occlusion_.setUniforms(*p, kOpaqueUnit, frame_.splatScale == 1);
    }
    if (terminationCheck()) frame_.terminated = true;
  }
}

bool SplatRenderer::slabsAdjacent(const Slab& a, const Slab& b) {
  const double gap =
      std::min(std::abs(a.farDepth - b.nearDepth), std::abs(b.farDepth - a.nearDepth));
  return gap <= 1e-6 * std::max(a.farDepth - a.nearDepth, b.farDepth - b.nearDepth);
}

void SplatRenderer::drawCompositeSlab(size_t s) {
  beginCompositeSlab(s);
  drawSlabRange(s, 0, slabInOrder(s).count);
  endCompositeSlab(s);
}

bool SplatRenderer::drawSlabChunks(double budgetMs, Clock::time_point start) {
  // Cost model, measured per chunk: msPerEntry_ per splat entry drawn and msPerSlabEnd_ per
  // slab finished (clear, blend under the image, termination check: passes over the whole
  // image). A chunk holds whole slabs while they fit; a slab too costly for the time left is
  // drawn in ranges of entries over several steps (its sums are order-independent, so the
  // picture is the same).
  // Entries drawn before anything is measured, and the fewest a range holds; both fewer where
  // the largest footprints are huge (a small volume filling the window: a few of its splats
  // cost as much as thousands of an ordinary view's).
  constexpr double kFirstFragments = 2.0e6;
  const size_t kFirstChunk =
      size_t(std::clamp(kFirstFragments / frame_.fragmentsPerEntry, 1.0, 2048.0));
  const size_t kMinRange = std::min<size_t>(512, kFirstChunk);
  constexpr size_t kFirstSlabEnds = 4;  // slabs finished before anything is measured
  const size_t n = frame_.slabs.size();
  const bool unlimited = !std::isfinite(budgetMs);
  const auto finished = [&] { return frame_.nextSlab >= n || frame_.terminated; };
  setSlabLoopState();
  while (!finished()) {
    // Milliseconds this chunk may take, and what it is expected to take so far.
    const double allowed = unlimited ? budgetMs : budgetMs - millisecondsSince(start);
    const bool measured = msPerEntry_ > 0.0;
    const auto chunkStart = Clock::now();
    size_t entries = 0, ends = 0;
    double expected = 0.0;
    while (!finished() && (entries + ends == 0 || expected < allowed)) {
      const size_t s = frame_.nextSlab;
      const size_t count = slabInOrder(s).count;
      const double wholeMs = msPerEntry_ * double(count) + msPerSlabEnd_;
      if (frame_.nextEntry == 0 &&
          (unlimited || (measured && expected + wholeMs <= allowed) ||
           (!measured && entries + count <= kFirstChunk && ends < kFirstSlabEnds))) {
        drawCompositeSlab(s);
        entries += count;
        ++ends;
        expected += wholeMs;
        frame_.drawnWeight += double(count) + frame_.meanEntries;
        ++frame_.nextSlab;
        continue;
      }
      if (frame_.nextEntry == 0) beginCompositeSlab(s);
      const double left = double(count - frame_.nextEntry);
      const double fit =
          measured ? (allowed - expected) / msPerEntry_ : double(kFirstChunk - entries);
      const size_t take = size_t(std::clamp(fit, std::min(double(kMinRange), left), left));
      drawSlabRange(s, frame_.nextEntry, take);
      frame_.nextEntry += take;
      entries += take;
      expected += msPerEntry_ * double(take);
      frame_.drawnWeight += double(take);
      if (frame_.nextEntry == count) {
        endCompositeSlab(s);
        ++ends;
        expected += msPerSlabEnd_;
        frame_.drawnWeight += frame_.meanEntries;
        frame_.nextEntry = 0;
        ++frame_.nextSlab;
      }
      if (!measured) break;  // one measurement before planning more
    }
    if (unlimited) continue;
    // llvmpipe does the GL work by glFinish: the chunk's time is only known after it.
    glFinish();
    updateCostModel(millisecondsSince(chunkStart), entries, ends);
    const double nextMs = msPerEntry_ * double(kMinRange) + msPerSlabEnd_;
    if (millisecondsSince(start) + nextMs > budgetMs) break;
  }
  endConditionalSlabs();  // the window draws between steps, the final pass after the last
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
  return finished();
}

void SplatRenderer::updateCostModel(double ms, size_t entries, size_t slabEnds) {
  // Up at once, down slowly: an overestimate costs a little speed, an underestimate a
  // stalled window.
  const auto blend = [](double old, double now) {
    return old > 0.0 && now < old ? 0.5 * (old + now) : now;
  };
  if (slabEnds == 0 || msPerEntry_ <= 0.0) {
    // Without a known per-entry cost the whole time is charged to the entries (safe: high).
    msPerEntry_ = blend(msPerEntry_, ms / double(std::max<size_t>(entries, 1)));
    return;
  }
  const double rest = std::max(0.0, ms - msPerEntry_ * double(entries));
  msPerSlabEnd_ = blend(msPerSlabEnd_, rest / double(slabEnds));
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
      const double fit = msPerEntry_ > 0.0 ? left / msPerEntry_ : double(kFirstChunk);
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
    updateCostModel(millisecondsSince(chunkStart), count, 0);
    if (millisecondsSince(start) + msPerEntry_ * double(kMinChunk) > budgetMs) break;
  }
  glBlendEquation(GL_FUNC_ADD);
  stats_.slabsDrawn = 1;
  return frame_.indirect || frame_.nextEntry >= all.count;
}

void SplatRenderer::bindFrameState() {
  if (frame_.texelBuffers) {
    // Texel-buffer views of the same buffers (their stores may have been re-specified).
    if (!splatTexels_) splatTexels_ = gl::Texture::create(GL_TEXTURE_BUFFER);
    if (!attributeTexels_) attributeTexels_ = gl::Texture::create(GL_TEXTURE_BUFFER);
    glTextureBuffer(splatTexels_.id(), GL_RG32UI, splatBuffer_.id());
    glTextureBuffer(attributeTexels_.id(), GL_RG32UI, attributeBuffer_.id());
    splatTexels_.bindUnit(kSplatTexelUnit);
    attributeTexels_.bindUnit(kAttributeTexelUnit);
  } else {
    splatBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    attributeBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  }
  // The CPU partition's order list is bound per draw (drawOrderRange).
  if (frame_.gpuSlabs) gpuPartition_->bindForDrawing();
  occlusion_.bindForDrawing(kOpaqueUnit);
  transferTexture_.bindUnit(0);
  if (frame_.pairedSlabs) pairTable_.bindUnits(kPairTableUnit, kPairPrefixUnit);
  gradients_.bindUnit(kGradientUnit);
  glBindVertexArray(emptyVao_.id());
  glViewport(0, 0, frame_.width, frame_.height);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glBlendEquation(GL_FUNC_ADD);
}

void SplatRenderer::render(const Camera& worldCamera, const RenderSettings& settings, int width,
                           int height) {
  beginFrame(worldCamera, settings, width, height);
  stepFrame(std::numeric_limits<double>::infinity());
}

void SplatRenderer::beginFrame(const Camera& worldCamera, const RenderSettings& settings, int width,
                               int height) {
  // Splats live in the volume's own frame; the camera moves instead (volume_orientation.h).
  const Camera camera = volume_ ? cameraInVolumeFrame(worldCamera, *volume_) : worldCamera;
  const auto start = Clock::now();
  waitForPartition();  // a cancelled frame's partition may still be running
  frame_ = FrameState{};
  frame_.camera = camera;
  frame_.settings = settings;
  frame_.width = width;
  frame_.height = height;
  frame_.pairedSlabs = pairedSlabs(settings);
  frame_.quarters = quarterSlabs(settings);
  frame_.slabPasses = slabPassesFor(settings);
  targets_.resize(width, height, frame_.pairedSlabs, frame_.quarters, voxelNormalSums(settings),
                  halfFloatSlabs(settings), coarseMarks(settings));
  stats_ = RenderStats{};
  stats_.slabPasses = frame_.quarters ? frame_.slabPasses : 0;
  const GLfloat zero[4] = {0, 0, 0, 0};
  glDisable(GL_SCISSOR_TEST);  // the whole images are cleared
  targets_.accumFbo.clearColor(0, zero);
  targets_.slabFbo.clearColor(0, zero);
  if (frame_.quarters) targets_.slabFbo.clearColor(2, zero);
  // Depth 0: below every slab's mark (slabMark).
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfi(targets_.slabFbo.id(), GL_DEPTH_STENCIL, 0, 0.0f, 0);
  const Classification classification = splatClassification(settings);
  if (volume_ && (splatsDirty_ || classification != classification_)) {
    const auto classifyStart = Clock::now();
    rebuildSplats(classification);
    stats_.classifyMs = millisecondsSince(classifyStart);
  }
  if (!frame_.pairedSlabs) pairTable_.release();
  auto stageStart = Clock::now();
  const Projection proj = camera.projection(width, height);
  frame_.proj = proj;
  const SplatSet& splats = classified_.splats;
  if (volume_ && splats.size() > 0 && camera.valid()) {
    const glm::dvec3& sp = volume_->spacing();
    const FootprintParams params = footprintParams(settings, sp);
    const bool composite = settings.mode == RenderMode::Composite;
    // X-ray and MIP take every splat at once: a single slab of unbounded thickness.
    const double thickness = composite ? slabThickness(settings, sp) : 1e30;
    DepthExtent extent;
    extent.reach = kernelReach(proj, settings.filter, settings.cutoff, sp, settings.kernelWidth,
                               settings.depthCutoff);
    extent.rotation = camera.rotation();
    extent.spacing = sp;
    extent.kernelWidth = settings.kernelWidth;
    if (frame_.pairedSlabs) stats_.classifyMs += preparePairTable(settings);
    syncAttributes(settings);
    frame_.gradientsPending = requestGradients(settings);  // on a worker: stepFrame waits
    stageStart = Clock::now();
    frame_.partitionStart = stageStart;
    frame_.reach = extent.reach;
    // Splats beyond a storage block: the GPU partition cannot read them, the CPU's can.
    frame_.texelBuffers = texelBuffers();
    frame_.gpuSlabs = gpuPartition() && !frame_.texelBuffers;
    stats_.gpuPartition = frame_.gpuSlabs;
    if (frame_.gpuSlabs) {
      if (!gpuPartition_) gpuPartition_ = std::make_unique<GpuSlabPartition>(shaders_);
      gpuPartition_->build(splatBuffer_, attributeBuffer_, splats.size(),
                           attributesUploaded_ && classified_.surfaceCount > 0, volume_->origin(),
                           camera.viewMatrix(), thickness, params.cullDepth, extent);
      frame_.slabs = gpuPartition_->slabs();
      frame_.indirect = !gpuPartition_->countsKnown();
      computeSlabRects();
      stats_.splatsDrawn = gpuPartition_->splatCount();
      prepareSlabs(gpuPartition_->nearestCenter());
    } else {
      // On a worker thread: a window's refinement step goes on drawing UI frames meanwhile
      // (stepFrame takes the result); the splats are not changed while it runs.
      const glm::dvec3 origin = volume_->origin();
      const glm::dmat4 view = camera.viewMatrix();
      const double cullDepth = params.cullDepth;
      frame_.partitionPending = true;
      pendingPartition_ = std::async(std::launch::async,
                                     [this, &splats, origin, view, thickness, cullDepth, extent] {
                                       partition_.build(splats, classified_.attributes, origin,
                                                        view, thickness, cullDepth, extent);
                                     });
    }
  }
  frame_.active = true;
  stats_.renderMs = millisecondsSince(start);
}

void SplatRenderer::takeCpuPartition(bool budgeted) {
  frame_.partitionPending = false;
  try {
    pendingPartition_.get();  // rethrows what the build threw (std::bad_alloc)
  } catch (...) {
    frame_.active = false;  // the frame ends here; the next beginFrame starts clean
    throw;
  }
  const auto& order = partition_.order();
  // The store's pages end where slabs do and are kept while big enough (OrderPages). A list of
  // more than one page goes up a page at a time over the following steps, each made as it is
  // reached (uploadOrderPieces); a whole frame copies it at once.
  std::vector<size_t> breaks;  // in order: the partition lays its slabs out front to back
  for (const Slab& slab : partition_.slabs()) breaks.push_back(slab.first);
  orderPages_.layout(breaks, order.size());
  frame_.orderUploading = budgeted && orderPages_.pages() > 1;
  frame_.orderUploaded = 0;
  if (!frame_.orderUploading) orderPages_.uploadAll(order.data());
  frame_.slabs = partition_.slabs();
  computeSlabRects();
  stats_.splatsDrawn = partition_.splatCount();
  prepareSlabs(partition_.nearestCenter());
}

bool SplatRenderer::uploadOrderPieces(double budgetMs, Clock::time_point start) {
  const uint32_t* order = partition_.order().data();
  do {
    orderPages_.uploadPage(frame_.orderUploaded++, order);
  } while (frame_.orderUploaded < orderPages_.pages() && millisecondsSince(start) < budgetMs);
  frame_.orderUploading = frame_.orderUploaded < orderPages_.pages();
  return !frame_.orderUploading;
}

void SplatRenderer::waitForPartition() {
  if (pendingPartition_.valid()) pendingPartition_.wait();
}

void SplatRenderer::prepareSlabs(double nearest) {
  const RenderSettings& settings = frame_.settings;
  const Projection& proj = frame_.proj;
  stats_.splatsTotal = classified_.splats.size();
  stats_.slabs = frame_.slabs.size();
  stats_.surfaceSplats = classified_.surfaceCount;
  if (frame_.slabs.empty()) return;
  const double reachPixels = pixelReach(frame_.reach, proj, nearest);
  stats_.quadPass = 2.0 * reachPixels + 0.5 > pointSizeLimit_;
  const double side = std::min(2.0 * reachPixels + 1.0, double(frame_.width + frame_.height));
  frame_.fragmentsPerEntry = std::max(1.0, side * side);
  // Not post-classified: there culling changed the picture (some 5000 pixels of a 96x80 test
  // scene), so it stays pre-classification's until that is understood.
  frame_.occlusion = occlusionCulling(settings.occlusionCulling) &&
                     settings.mode == RenderMode::Composite &&
                     settings.order == CompositeOrder::FrontToBack &&
                     settings.terminationOpacity < 1.0 && !postClassified(settings);
  if (frame_.occlusion) {
    occlusion_.resize(frame_.width, frame_.height);
    occlusion_.resetCount();
  }
  setFrameUniforms();
  frame_.drawSplats = true;
  setFrameWeights();
  // The partition (its upload or its compute passes and the range read back; on the CPU, from
  // the worker's start).
  stats_.partitionMs = millisecondsSince(frame_.partitionStart);
}

void SplatRenderer::setFrameUniforms() {
  const RenderSettings& settings = frame_.settings;
  splatPrograms_.select(splatVariant(settings, frame_.texelBuffers));
  setCommonUniforms(splatPrograms_.point(), frame_.camera, frame_.proj, settings);
  setCommonUniforms(splatPrograms_.quad(), frame_.camera, frame_.proj, settings);
  setSlabPassUniforms(frame_.proj, settings);
  // The splat programs now hold the picture's own scale (setSplatScale sets a coarser one), and
  // culling as the frame has it so far (a pyramid built mid-frame, when set again then).
  frame_.splatScale = 1.0;
  if (frame_.pyramidBuilt)
    for (gl::Program* p : splatPrograms_.both()) occlusion_.setUniforms(*p, kOpaqueUnit, true);
  programs_->user = this;
}

void SplatRenderer::setFrameWeights() {
  const size_t entries = frameEntryCount();
  const size_t slabCount = frame_.slabs.size();
  frame_.meanEntries = double(entries) / double(std::max<size_t>(1, slabCount));
  frame_.totalWeight = frame_.settings.mode == RenderMode::Composite
                           ? double(entries) + frame_.meanEntries * double(slabCount)
                           : double(frame_.slabs.empty() ? 0 : frame_.slabs.front().count);
}

void SplatRenderer::takeGpuCounts() {
  gpuPartition_->readCounts();
  frame_.slabs.clear();
  for (const Slab& slab : gpuPartition_->slabs())
    if (slab.count > 0) frame_.slabs.push_back(slab);
  frame_.indirect = false;
  computeSlabRects();
  setSlabPassUniforms(frame_.proj, frame_.settings);  // the scales may ask for the coarser pass
  stats_.slabs = frame_.slabs.size();
  setFrameWeights();
}

bool SplatRenderer::stepFrame(double budgetMs) {
  if (!frame_.active) return true;
  const auto start = Clock::now();
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
  if (frame_.drawSplats && tilesFitStep(budgetMs) && tilesWanted(frame_.settings) &&
      frame_.settings.mode == RenderMode::Composite && frame_.nextSlab == 0 && drawTiles()) {
    frame_.drawSplats = false;
    stats_.splatMs += millisecondsSince(drawStart);  // the tiles wait for their passes
  }
  if (frame_.drawSplats) {
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
  }
  if (frame_.timed) glQueryCounter(timers_[1], GL_TIMESTAMP);
  drawFinalPass();
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
  // partition's entries are only counted above).
  if (frame_.timed && frame_.quarters && frame_.settings.slabPasses == 0 && !frame_.tiles &&
      stats_.slabEntries > 0)
    passTuner_.report(frame_.slabPasses - 1, stats_.splatMs / double(stats_.slabEntries));
  reportSplatterCost();
  frame_.active = false;
  stats_.renderMs += millisecondsSince(start);
  return true;
}

double SplatRenderer::frameProgress() const {
  if (!frame_.active) return 1.0;
  return frame_.totalWeight > 0.0 ? std::min(1.0, frame_.drawnWeight / frame_.totalWeight) : 0.0;
}

void SplatRenderer::drawFinalPass() {
  const RenderSettings& settings = frame_.settings;
  const auto stageStart = Clock::now();
  glBindVertexArray(emptyVao_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.outputFbo.id());
  glViewport(0, 0, frame_.width, frame_.height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  targets_.slab.bindUnit(1);
  // Front to back, premultiplied, over nothing: the tiles' picture is what the slab loop leaves.
  (frame_.tiles ? tiles_->pictureTexture() : targets_.accum).bindUnit(2);
  finalProgram_.setInt("uSlab", 1);
  finalProgram_.setInt("uImage", 2);
  finalProgram_.setInt("uMode", int(settings.mode));
  finalProgram_.setInt("uXRayMap", int(settings.xrayMap));
  finalProgram_.setFloat("uXRayScale", float(settings.xrayScale));
  finalProgram_.setVec3("uBackground", glm::vec3(settings.background));
  glUseProgram(finalProgram_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  if (frame_.timed) {
    // The last timestamp's result waits for the GPU, as glFinish would; the others are there.
    glQueryCounter(timers_[2], GL_TIMESTAMP);
    GLuint64 t[3] = {0, 0, 0};
    for (int i = 2; i >= 0; --i) glGetQueryObjectui64v(timers_[i], GL_QUERY_RESULT, &t[i]);
    stats_.splatMs += frame_.drawSplats && t[1] > t[0] ? double(t[1] - t[0]) * 1e-6 : 0.0;
    stats_.compositeMs = t[2] > t[1] ? double(t[2] - t[1]) * 1e-6 : 0.0;
    gl::checkGlError("SplatRenderer::render");
    return;
  }
  glFinish();
  gl::checkGlError("SplatRenderer::render");
  stats_.compositeMs = millisecondsSince(stageStart);
}

}  // namespace ewa

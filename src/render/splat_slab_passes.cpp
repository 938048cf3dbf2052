// SplatRenderer's slabs: their rectangles and image scales, the splats of one slab drawn into
// its images, and its composite pass (classification, marks and the termination check).
#include <algorithm>
#include <cmath>

#include "core/clip_share.h"
#include "core/kernel_reach.h"
#include "render/splat_renderer.h"

namespace ewa {

namespace {

// Front to back, the opaque pixels are marked and counted after every this many slabs: often
// enough to stop soon after the picture is opaque, rarely enough to cost little.
constexpr size_t kCheckEvery = 4;

}  // namespace

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
  // The crop box's part of the volume: a kernel beside it adds only along rays through it.
  const DataBox kept = keptBoxInVolumeFrame(settings.clip, *volume_);
  for (const Slab& slab : frame_.slabs)
    frame_.slabRects.push_back(slabPixelRect(view, frame_.proj, reach, kept.low - margin,
                                             kept.high + margin, slab.nearDepth, slab.farDepth,
                                             params.cullDepth));
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
  if (!slabRectsInUse()) return;
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
  // writes every pixel, which lengthens frames), GPUs have fast clears too, and on
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
  // Each picture pixel takes the texel its centre lies in (scaledCoordinate); the caller's
  // scissor keeps the blit to the rows of the slab's rectangle it passes.
  const BlitRects r = coarseToPictureBlit(frame_.width, frame_.height, slabScale(s));
  glBlitNamedFramebuffer(targets_.slabCoarseTarget(slabImageOf(s)).id(), targets_.accumFbo.id(),
                         r.source.x0, r.source.y0, r.source.x1, r.source.y1, r.destination.x0,
                         r.destination.y0, r.destination.x1, r.destination.y1, GL_DEPTH_BUFFER_BIT,
                         GL_NEAREST);
}

bool SplatRenderer::slabRectsInUse() const {
  return slabScissor_ && frame_.slabRects.size() == frame_.slabs.size();
}

PixelRect SplatRenderer::slabPassRect(size_t s) const {
  if (slabRectsInUse()) return frame_.slabRects[slabPosition(s)];
  return PixelRect{0, 0, frame_.width, frame_.height};
}

void SplatRenderer::passSlabRows(size_t s, int y0, int y1) {
  // Each pixel's pass reads only its own texels (and the coarse image's nearby ones) and
  // blends into its own pixel: a band of rows gives those rows exactly what a whole pass does.
  PixelRect band = slabPassRect(s);
  band.y0 = std::max(band.y0, y0);
  band.y1 = std::min(band.y1, y1);
  if (band.empty()) return;
  const bool frontToBack = frame_.settings.order == CompositeOrder::FrontToBack;
  scissorTo(band);
  // Between slabs: 1 - exp(-depth) composited under (front to back) or over (back to front).
  if (slabScale(s) > 1.0) blitCoarseMarks(s);
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
    const bool adjacent = s > 0 && ewa::slabsAdjacent(slabInOrder(s - 1), slabInOrder(s));
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
}

void SplatRenderer::closeSlab(size_t s) {
  const RenderSettings& settings = frame_.settings;
  const size_t n = frame_.slabs.size();
  if (frame_.slabRects.size() == n)
    frame_.markRect = frame_.markRect.unite(frame_.slabRects[slabPosition(s)]);
  ++stats_.slabsDrawn;
  if (slabScale(s) > 1) ++stats_.slabsCoarse;
  if (finishChecks(s)) {
    // Mark pixels that reached the threshold; later splat fragments there fail the stencil.
    // Only the slabs composited since the last marks changed the image: their rectangles.
    if (slabRectsInUse())
      scissorTo(frame_.markRect);
    else
      glDisable(GL_SCISSOR_TEST);  // the last band's scissor would hold the marks to it
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
    if (terminationCheck(slabInOrder(s + 1).nearDepth)) frame_.terminated = true;
  }
}

bool SplatRenderer::finishChecks(size_t s) const {
  return terminates() && (s + 1) % kCheckEvery == 0 && s + 1 < frame_.slabs.size();
}

}  // namespace ewa

// SplatRenderer's frame set-up and end: the bound state, the slab partition (CPU worker or
// GPU) and its upload, the per-frame uniforms and weights, the final picture.
#include <algorithm>
#include <chrono>
#include <future>
#include <limits>

#include "core/kernel_reach.h"
#include "core/stopwatch.h"
#include "core/volume_orientation.h"
#include "gl/gl_error.h"
#include "render/splat_renderer.h"

namespace ewa {

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
  frame_.targetLayout = targetLayout(settings, width, height);
  stats_ = RenderStats{};
  stats_.slabPasses = frame_.quarters ? frame_.slabPasses : 0;
  // Images of a new size are made in the steps (prepareTargets), a few a step.
  frame_.targetsPending = !targets_.ready(frame_.targetLayout);
  if (!frame_.targetsPending) clearTargets();
  const Classification classification = splatClassification(settings);
  if (upload_ && upload_->classification() == classification) installUpload();
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
    lastRotation_ = camera.rotation();
    const double thickness = composite ? slabThickness(settings, sp, lastRotation_) : 1e30;
    DepthExtent extent;
    extent.reach = kernelReach(proj, settings.filter, settings.cutoff, sp, settings.kernelWidth,
                               settings.depthCutoff);
    extent.rotation = camera.rotation();
    extent.spacing = sp;
    extent.kernelWidth = settings.kernelWidth;
    extent.anchorDepth = slabAnchor_;
    if (frame_.pairedSlabs) stats_.classifyMs += preparePairTable(settings, thickness);
    syncAttributes(settings);
    frame_.gradientsPending = requestGradients(settings);  // on a worker: stepFrame waits
    stageStart = Clock::now();
    frame_.partitionStart = stageStart;
    frame_.reach = extent.reach;
    // Splats beyond a storage block: the GPU partition cannot read them, the CPU's can.
    frame_.texelBuffers = texelBuffers();
    // The CPU splatter reads the CPU partition's lists.
    frame_.cpuFrame = cpuWanted(settings);
    frame_.gpuSlabs = gpuPartition() && !frame_.texelBuffers && !frame_.cpuFrame;
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

void SplatRenderer::clearTargets() {
  const GLfloat zero[4] = {0, 0, 0, 0};
  glDisable(GL_SCISSOR_TEST);  // the whole images are cleared
  targets_.accumFbo.clearColor(0, zero);
  targets_.slabFbo.clearColor(0, zero);
  if (frame_.quarters) targets_.slabFbo.clearColor(2, zero);
  // Depth 0: below every slab's mark (slabMark).
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfi(targets_.slabFbo.id(), GL_DEPTH_STENCIL, 0, 0.0f, 0);
}

bool SplatRenderer::prepareTargets(double budgetMs) {
  if (!frame_.targetsPending) return true;
  if (!targets_.prepare(frame_.targetLayout, budgetMs, uploads_)) return false;
  clearTargets();
  frame_.targetsPending = false;
  return true;
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
  frame_.slabs = partition_.slabs();
  stats_.splatsDrawn = partition_.splatCount();
  if (frame_.cpuFrame) {  // the CPU splatter reads the lists where they are
    prepareSlabs(partition_.nearestCenter());
    return;
  }
  // The store's pages end where slabs do and are kept while big enough (OrderPages). A list of
  // more than one page goes up a page at a time over the following steps, each made as it is
  // reached (uploadOrderPieces); a whole frame copies it at once.
  std::vector<size_t> breaks;  // in order: the partition lays its slabs out front to back
  for (const Slab& slab : partition_.slabs()) breaks.push_back(slab.first);
  orderPages_.layout(breaks, order.size());
  frame_.orderUploading = budgeted && orderPages_.pages() > 1;
  frame_.orderUploaded = 0;
  if (!frame_.orderUploading) orderPages_.uploadAll(order.data());
  computeSlabRects();
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
  cancelCpu();  // it reads the partition's lists
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
  frame_.occlusion = !frame_.cpuFrame && occlusionCulling(settings.occlusionCulling) &&
                     settings.mode == RenderMode::Composite &&
                     settings.order == CompositeOrder::FrontToBack &&
                     settings.terminationOpacity < 1.0 && !postClassified(settings);
  if (frame_.occlusion) {
    occlusion_.resize(frame_.width, frame_.height);
    occlusion_.resetCount();
  }
  if (!frame_.cpuFrame) setFrameUniforms();  // the CPU frame's state is C++ (cpuSplatSetup)
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
  // The final pass, which budgeted steps draw in bands: as much as a slab's pass (X-ray, MIP:
  // a hundredth of their one slab).
  frame_.finalWeight =
      std::max(1.0, frame_.settings.mode == RenderMode::Composite ? frame_.meanEntries
                                                                  : 0.01 * frame_.totalWeight);
  frame_.totalWeight += frame_.finalWeight;
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

void SplatRenderer::drawFinalPass(int y0, int y1) {
  const RenderSettings& settings = frame_.settings;
  const auto stageStart = Clock::now();
  glBindVertexArray(emptyVao_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.outputFbo.id());
  glViewport(0, 0, frame_.width, frame_.height);
  glDisable(GL_BLEND);
  const bool whole = y0 <= 0 && y1 >= frame_.height;
  if (whole) {
    glDisable(GL_SCISSOR_TEST);
  } else {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, y0, frame_.width, y1 - y0);
  }
  // X-ray and MIP drawn on the CPU: its picture is the slab image.
  (frame_.cpu && settings.mode != RenderMode::Composite ? cpu_->pictureTexture() : targets_.slab)
      .bindUnit(1);
  // Front to back, premultiplied, over nothing: the tiles' picture is what the slab loop leaves.
  (frame_.tiles ? tiles_->pictureTexture()
   : frame_.cpu ? cpu_->pictureTexture()
                : targets_.accum)
      .bindUnit(2);
  finalProgram_.setInt("uSlab", 1);
  finalProgram_.setInt("uImage", 2);
  finalProgram_.setInt("uMode", int(settings.mode));
  finalProgram_.setInt("uXRayMap", int(settings.xrayMap));
  finalProgram_.setFloat("uXRayScale", float(settings.xrayScale));
  finalProgram_.setVec3("uBackground", glm::vec3(settings.background));
  glUseProgram(finalProgram_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  if (y1 >= frame_.height) targets_.outputFinished();
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
  const double ms = millisecondsSince(stageStart);
  stats_.compositeMs += ms;
  finalMsPerPixel_ = ms / std::max(1.0, double(frame_.width) * double(y1 - y0));
}

}  // namespace ewa

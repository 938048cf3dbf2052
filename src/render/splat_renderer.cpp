// SplatRenderer: classification into splats, per-frame uniforms, splat drawing and read-back.
#include "render/splat_renderer.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "core/clip_share.h"
#include "core/named_values.h"
#include "core/stopwatch.h"
#include "gl/gl_error.h"
#include "render/clip_uniforms.h"
#include "render/gl_limits.h"

namespace ewa {

namespace {
constexpr int kTransferSamples = 4096;
constexpr NamedValue<PartitionMode> kPartitionModeNames[] = {
    {PartitionMode::Auto, "auto"}, {PartitionMode::Gpu, "gpu"}, {PartitionMode::Cpu, "cpu"}};
}  // namespace

const char* partitionModeName(PartitionMode mode) {
  return nameIn(kPartitionModeNames, mode);
}

bool parsePartitionMode(const std::string& text, PartitionMode* mode) {
  return parseIn(kPartitionModeNames, text, mode);
}

SplatRenderer::SplatRenderer(const gl::ShaderLibrary& shaders,
                             std::shared_ptr<SplatProgramSet> programs)
    : shaders_(shaders),
      programs_(programs ? std::move(programs) : std::make_shared<SplatProgramSet>(shaders)),
      splatPrograms_(programs_->splat),
      slabPrograms_(programs_->slab),
      markProgram_(programs_->mark),
      finalProgram_(programs_->final),
      boxProgram_(programs_->box),
      occlusion_(shaders),
      emptyVao_(gl::VertexArray::create()),
      transferTexture_(gl::Texture::create1D(GL_RGBA32F, kTransferSamples)) {
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, range);
  GLint viewportDims[2] = {16384, 16384};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewportDims);
  maxViewport_ = std::min(viewportDims[0], viewportDims[1]);
  glPointSizeLimit_ = pointSizeLimit_ = std::max(1.0f, range[1]);
  transferTexture_.setFilter(GL_LINEAR, GL_LINEAR);
  transferTexture_.setWrap(GL_CLAMP_TO_EDGE);
  // The splat list must fit one shader storage block and, on the CPU, the machine's memory.
  GLint64 block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  maxStorageBlockBytes_ = uint64_t(std::max<GLint64>(block, 0));
  GLint alignment = 256, texels = 0;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  storageAlignment_ = uint64_t(std::max(alignment, 4));
  maxTexelBufferTexels_ = uint64_t(std::max(texels, 0));
  // Beyond a storage block the splats are read from texel buffers (one texel a splat).
  const uint64_t bufferBytes =
      std::max(maxStorageBlockBytes_, maxTexelBufferTexels_ * sizeof(PackedSplat));
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  const uint64_t memory = pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : ~0ull;
  glMaxSplats_ = maxSplats_ = size_t(std::min(bufferBytes, memory / 2) / sizeof(PackedSplat));
  glCreateQueries(GL_SAMPLES_PASSED, 2, queries_);
  glCreateQueries(GL_TIMESTAMP, 3, timers_);
  softwareGl_ = softwareRasterizer();
  laggedTermination_ = !softwareGl_;
  gpuTimers_ = !softwareGl_;
}

bool SplatRenderer::gpuPartition() const {
  return partitionMode_ == PartitionMode::Gpu ||
         (partitionMode_ == PartitionMode::Auto && !softwareGl_);
}

SplatRenderer::~SplatRenderer() {
  waitForPartition();
  if (queries_[0]) glDeleteQueries(2, queries_);
  if (timers_[0]) glDeleteQueries(3, timers_);
  if (programs_->user == this) programs_->user = nullptr;  // another renderer may get this address
}

uint64_t SplatRenderer::storageBlockBytes() const {
  // At least a few alignments: the order list's windows must hold entries.
  return storageBlockLimit_ > 0
             ? std::max(std::min(storageBlockLimit_, maxStorageBlockBytes_), 8 * storageAlignment_)
             : maxStorageBlockBytes_;
}

bool SplatRenderer::texelBuffers() const {
  return uint64_t(classified_.splats.size()) * sizeof(PackedSplat) > storageBlockBytes();
}

RenderStats SplatRenderer::stats() const {
  RenderStats s = stats_;
  s.gpuBytes = size_t(splatBuffer_.size() + attributeBuffer_.size()) + orderPages_.bytes() +
               size_t(kTransferSamples) * 4 * sizeof(float) + targets_.bytes() +
               (gpuPartition_ ? gpuPartition_->bytes() : 0) + occlusion_.bytes() +
               pairTable_.bytes() + (tiles_ ? tiles_->bytes() : 0) + gradients_.bytes();
  return s;
}

void SplatRenderer::setPointSizeLimit(float limit) {
  pointSizeLimit_ = std::clamp(limit, 1.0f, glPointSizeLimit_);
}

void SplatRenderer::setVolume(const Volume& volume) {
  volume_ = &volume;
  gradients_.invalidate();
  splatsDirty_ = true;
  passTuner_.reset();  // another volume: both ways timed again
  splatterTuner_.reset();
}

void SplatRenderer::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  splatsDirty_ = true;
}

void SplatRenderer::rebuildSplats(const Classification& classification) {
  splatsDirty_ = false;
  classification_ = classification;
  uploadTransferTexture();
  classified_ = ClassifiedSplats();
  try {
    // Gradients and surface voxels are found here, once per volume, transfer function and
    // classification; camera and light changes only change uniforms.
    classified_ = classifySplats(*volume_, tf_, classification, maxSplats_);
  } catch (const SplatLimitError&) {
    splatsDirty_ = true;  // nothing drawn until the volume or transfer function changes
    throw gl::GlError("volume: more than " + std::to_string(maxSplats_) +
                      " visible voxels; the splat buffer (8 bytes a voxel) may hold at most " +
                      std::to_string(maxSplats_ * sizeof(PackedSplat)) +
                      " bytes (GL_MAX_TEXTURE_BUFFER_SIZE texels, a storage block, half the "
                      "machine's memory): make more of the volume transparent");
  }
  uploadSplats();
}

void SplatRenderer::uploadTransferTexture() {
  const double lo = volume_->minValue(), hi = volume_->maxValue();
  const std::vector<glm::vec4> table = tf_.bake(lo, hi, kTransferSamples);
  transferTexture_.subImage1D(0, 0, kTransferSamples, GL_RGBA, GL_FLOAT, table.data());
  pairTable_.invalidate();
}

void SplatRenderer::updateTransferTexture(const TransferFunction& tf) {
  tf_ = tf;
  if (volume_) uploadTransferTexture();
}

void SplatRenderer::setSplats(ClassifiedSplats splats, const Classification& classification) {
  waitForPartition();  // the worker reads the splats being replaced
  classified_ = std::move(splats);
  classification_ = classification;
  splatsDirty_ = false;
  uploadSplats();
}

void SplatRenderer::uploadSplats() {
  // Order entries keep two flag bits above the splat index.
  if (classified_.splats.size() > SlabPartition::kIndexMask) {
    classified_ = ClassifiedSplats{};
    splatsDirty_ = true;
    throw gl::GlError("volume: more than 2^30 visible voxels: not supported by splatting");
  }
  // The order list's store is kept between frames (takeCpuPartition); a new splat set starts
  // it afresh, so a small volume after a big one does not hold the big one's store.
  if (!frame_.active) orderPages_.clear();
  const size_t n = std::max<size_t>(1, classified_.splats.size());
  const auto& splats = classified_.splats.splats();
  splatBuffer_.setData(GLsizeiptr(n * sizeof(PackedSplat)),
                       splats.empty() ? nullptr : splats.data(), GL_STATIC_DRAW);
  // GL_OUT_OF_MEMORY here names the buffer instead of surfacing at the end of the frame.
  gl::checkGlError(("splat buffer upload (" + std::to_string(n) + " splats)").c_str());
  attributesUploaded_ = false;  // the next frame uploads them if it needs them
}

void SplatRenderer::syncAttributes(const RenderSettings& settings) {
  const bool needed =
      (settings.lighting.enabled && !fieldNormals(settings) && !rayNormals(settings)) ||
      classified_.surfaceCount > 0;
  const size_t n = classified_.splats.size();
  if (needed && !attributesUploaded_ && classified_.attributes.size() == n && n > 0) {
    attributeBuffer_.setData(GLsizeiptr(n * sizeof(PackedAttributes)),
                             classified_.attributes.data(), GL_STATIC_DRAW);
    gl::checkGlError(("splat attribute upload (" + std::to_string(n) + " splats)").c_str());
    attributesUploaded_ = true;
  } else if (!needed && (attributesUploaded_ || !attributeBuffer_)) {
    // A 16-byte placeholder keeps binding 2 valid; the shaders do not read it.
    attributeBuffer_.setData(16, nullptr, GL_STATIC_DRAW);
    attributesUploaded_ = false;
  }
}

void SplatRenderer::setCommonUniforms(gl::Program& p, const Camera& camera, const Projection& proj,
                                      const RenderSettings& settings) {
  const glm::dvec3& sp = volume_->spacing();
  const FootprintParams params = footprintParams(settings, sp);
  const Lighting& light = settings.lighting;
  p.setMat4("uView", glm::mat4(camera.viewMatrix()));
  const glm::dvec3 sigma = kernelSigma(sp, settings.kernelWidth);
  p.setMat3("uCovariance", glm::mat3(cameraCovariance(camera.rotation(), sigma)));
  p.setVec3("uKernelSigma", glm::vec3(sigma));
  p.setVec3("uOrigin", glm::vec3(volume_->origin()));
  p.setVec3("uSpacing", glm::vec3(sp));
  p.setFloat("uVoxelVolume", float(sp.x * sp.y * sp.z));
  p.setFloat("uMaxSigma", float(std::max({sigma.x, sigma.y, sigma.z})));
  p.setInt("uOrthographic", proj.orthographic ? 1 : 0);
  setProjectionUniforms(p, proj, params.lowPass);
  p.setInt("uFilter", int(params.filter));
  p.setFloat("uCutoff", float(params.cutoff));
  p.setFloat("uDepthCutoff", float(frame_.reach.depthCutoff));  // the partition's reach
  const DepthProfile profile = depthProfile(settings);
  p.setVec2("uDepthProfile", glm::vec2(profile.erfReach, profile.scale));
  p.setFloat("uMinSpacing", float(params.minSpacing));
  p.setFloat("uSwanSpacing", float(params.swanSpacing));
  p.setFloat("uCullDepth", float(params.cullDepth));
  p.setFloat("uPointSizeLimit", pointSizeLimit_);
  p.setInt("uTransfer", 0);
  p.setFloat("uSurfaceTau",
             float(-std::log(1.0 - std::clamp(settings.surfaceOpacity, 0.0, 0.999999))));
  p.setInt("uShading", light.enabled ? 1 : 0);
  p.setFloat("uAmbient", float(light.ambient));
  p.setFloat("uDiffuse", float(light.diffuse));
  p.setFloat("uSpecular", float(light.specular));
  p.setFloat("uShininess", float(std::max(light.shininess, 1e-3)));
  setClipUniforms(p, settings.clip, *volume_, camera, proj);  // planes; rays again per scale
  p.setInt("uAttributes", attributesUploaded_ ? 1 : 0);
  p.setInt("uSplatTexels", int(kSplatTexelUnit));
  p.setInt("uAttributeTexels", int(kAttributeTexelUnit));
  occlusion_.setUniforms(p, kOpaqueUnit, false);  // until the frame's first pyramid
}

void SplatRenderer::setProjectionUniforms(gl::Program& p, const Projection& proj,
                                          double lowPass) const {
  p.setFloat("uFocalPixels", float(proj.focalPixels));
  p.setFloat("uPixelsPerUnit", float(proj.pixelsPerUnit));
  p.setVec2("uViewport", glm::vec2(proj.width, proj.height));
  p.setVec2("uPrincipal", glm::vec2(proj.principal));
  // The GL viewport the splats are drawn with (drawSplats): the image and a guard band.
  const float guard = float(guardBand(proj));
  p.setVec4("uViewportRect", glm::vec4(-guard, -guard, float(proj.width) + 2.0f * guard,
                                       float(proj.height) + 2.0f * guard));
  p.setFloat("uLowPass", float(lowPass));
}

void SplatRenderer::setSplatScale(double scale) {
  if (scale == frame_.splatScale) return;
  frame_.splatScale = scale;
  const Projection proj = scaledProjection(frame_.proj, scale);
  // The footprints are the picture's, low-pass filter included, sampled on coarser texels and
  // narrowed by the blur of the bilinear read-back (kBilinearReadVariance).
  const double lowPass = lowPassVariance(frame_.settings) / (scale * scale) -
                         (scale > 1.0 ? kBilinearReadVariance : 0.0);
  for (gl::Program* p : splatPrograms_.both()) {
    setProjectionUniforms(*p, proj, lowPass);
    // The clip rays of the coarser image's pixels.
    setClipUniforms(*p, frame_.settings.clip, *volume_, frame_.camera, proj);
    // The opacity pyramid is the picture's pixels: coarser images are not culled.
    occlusion_.setUniforms(*p, kOpaqueUnit, frame_.pyramidBuilt && scale == 1);
  }
}

bool SplatRenderer::postClassified(const RenderSettings& settings) {
  return ewa::postClassified(settings);
}

bool SplatRenderer::fieldNormals(const RenderSettings& settings) {
  return pairedSlabs(settings) && settings.lighting.enabled &&
         settings.postNormals == PostNormals::Field;
}

bool SplatRenderer::rayNormals(const RenderSettings& settings) {
  return postClassified(settings) && settings.lighting.enabled &&
         settings.postNormals == PostNormals::Ray;
}

bool SplatRenderer::voxelNormalSums(const RenderSettings& settings) {
  return postClassified(settings) && settings.lighting.enabled && !fieldNormals(settings) &&
         !rayNormals(settings);
}

bool SplatRenderer::requestGradients(const RenderSettings& settings) {
  if (!volume_ || !rayNormals(settings)) {
    gradients_.releaseWhenIdle();  // not wanted: freed once no worker packs it
    return false;
  }
  const GradientMode mode = settings.classification.gradient;
  gradients_.request(*volume_, mode);  // nothing when the texture holds them already
  return !gradients_.holds(*volume_, mode);
}

SplatVariant SplatRenderer::splatVariant(const RenderSettings& settings, bool texelBuffers) const {
  SplatVariant variant;
  variant.mip = settings.mode == RenderMode::Mip;
  variant.post = postClassified(settings);
  variant.halves = pairedSlabs(settings);
  variant.quarters = quarterSlabs(settings);
  variant.clip = volume_ && !halfSpacesInVolumeFrame(settings.clip, *volume_).empty();
  variant.texelBuffers = texelBuffers;
  variant.erfSeries = usesErfSeries(depthProfile(settings));
  return variant;
}

SlabPassVariant SplatRenderer::slabPassVariant(const RenderSettings& settings, bool scaled) const {
  SlabPassVariant variant;
  variant.post = postClassified(settings);
  variant.preintegrated = pairedSlabs(settings);
  variant.shading = variant.post && settings.lighting.enabled;  // pre-classified: in the sums
  variant.fieldNormals = fieldNormals(settings);
  variant.rayNormals = rayNormals(settings);
  // Front to back the slab drawn before is the segment's front, back to front its back.
  variant.neighbourInFront = variant.preintegrated && settings.order == CompositeOrder::FrontToBack;
  variant.scaled = scaled;
  variant.quarters = quarterSlabs(settings);
  return variant;
}

void SplatRenderer::prepare(const RenderSettings& settings, int width, int height) {
  if (width > 0 && height > 0)
    targets_.resize(width, height, pairedSlabs(settings), quarterSlabs(settings),
                    voxelNormalSums(settings), halfFloatSlabs(settings), coarseMarks(settings));
  splatPrograms_.select(splatVariant(settings, false));
  programs_->user = nullptr;  // the current variant changed: a frame under way sets its own again
  if (settings.mode != RenderMode::Composite) return;
  slabPrograms_.select(slabPassVariant(settings, false));
  if (settings.coarseSlabs) slabPrograms_.select(slabPassVariant(settings, true));
  if (volume_ && pairedSlabs(settings)) preparePairTable(settings);
  requestGradients(settings);  // packed on a worker from now on
}

bool SplatRenderer::coarseMarks(const RenderSettings& settings) {
  return settings.coarseSlabs && settings.mode == RenderMode::Composite;
}

bool SplatRenderer::pairedSlabs(const RenderSettings& settings) {
  return postClassified(settings) && settings.slabPreintegration;
}

bool SplatRenderer::quarterSlabs(const RenderSettings& settings) {
  return pairedSlabs(settings) && settings.slabSamples >= 4;
}

int SplatRenderer::slabPassesFor(const RenderSettings& settings) const {
  if (settings.slabPasses == 1 || settings.slabPasses == 2) return settings.slabPasses;
  // Auto: timed frames choose where the GPU's timers are used (not on software rasterizers,
  // where two passes always cost more: the fragments are the cost).
  return gpuTimers_ ? 1 + passTuner_.choice() : 1;
}

double SplatRenderer::slabThickness(const RenderSettings& settings, const glm::dvec3& spacing) {
  return std::max(0.25, settings.slabThickness) * footprintParams(settings, spacing).minSpacing;
}

double SplatRenderer::preparePairTable(const RenderSettings& settings) {
  // Segments run between the values of half (quarter) slabs: the table's colours (their
  // self-attenuation) are for that length.
  const double thickness = slabThickness(settings, volume_->spacing());
  const double samples = quarterSlabs(settings) ? 4.0 : 2.0;
  return pairTable_.prepare(tf_, volume_->minValue(), volume_->maxValue(), thickness / samples);
}

void SplatRenderer::setSlabPassUniforms(const Projection& proj, const RenderSettings& settings) {
  const bool coarser = std::any_of(frame_.slabScales.begin(), frame_.slabScales.end(),
                                   [](double scale) { return scale > 1.0; });
  slabPass_[1] = nullptr;
  for (int scaled = coarser ? 1 : 0; scaled >= 0; --scaled) {
    gl::Program& p = slabPrograms_.select(slabPassVariant(settings, scaled == 1));
    slabPass_[scaled] = &p;
    p.setInt("uTransfer", 0);
    p.setInt("uSlabNormal", 3);
    p.setVec2("uViewport", glm::vec2(proj.width, proj.height));
    setClassifyUniforms(p, proj, settings);
    p.setInt("uNeighbourSlab", int(kNeighbourSlabUnit));
    p.setInt("uSlabBack", int(kSlabBackUnit));
    p.setInt("uNeighbourBack", int(kNeighbourBackUnit));
    p.setInt("uSlab", 1);
    p.setFloat("uSlabScale", 1.0f);
    p.setFloat("uNeighbourScale", 1.0f);
  }
}

void SplatRenderer::setClassifyUniforms(gl::Program& p, const Projection& proj,
                                        const RenderSettings& settings) {
  const Lighting& light = settings.lighting;
  p.setInt("uOrthographic", proj.orthographic ? 1 : 0);
  p.setFloat("uFocalPixels", float(proj.focalPixels));
  p.setInt("uShading", light.enabled ? 1 : 0);
  p.setFloat("uAmbient", float(light.ambient));
  p.setFloat("uDiffuse", float(light.diffuse));
  p.setFloat("uSpecular", float(light.specular));
  p.setFloat("uShininess", float(std::max(light.shininess, 1e-3)));
  p.setFloat("uPixelsPerUnit", float(proj.pixelsPerUnit));
  // Post-classified: the covered lengths end at the data's box.
  setDataBoxUniforms(p, *volume_, frame_.camera, proj);
  // Samplers of different types must not share a unit, used or not.
  p.setInt("uPairTable", int(kPairTableUnit));
  p.setInt("uPairPrefix", int(kPairPrefixUnit));
  p.setInt("uGradient", int(kGradientUnit));
}

void SplatRenderer::setSlabUniforms(const Slab& slab, bool split, bool openTails, int slabIndex) {
  for (gl::Program* p : splatPrograms_.both()) {
    p->setInt("uSlabIndex", slabIndex);
    p->setInt("uSplitDepth", split ? 1 : 0);
    p->setInt("uOpenTails", openTails ? 1 : 0);
    p->setFloat("uSlabNear", float(slab.nearDepth));
    p->setFloat("uSlabFar", float(slab.farDepth));
  }
}

int SplatRenderer::guardBand(const Projection& image) const {
  const int room = (maxViewport_ - std::max(image.width, image.height)) / 2;
  return std::clamp(int(std::ceil(0.5 * pointSizeLimit_)) + 2, 0, std::max(room, 0));
}

void SplatRenderer::drawSplats(const Slab& slab, bool quads, int slabIndex) {
  // GL drops a point whose centre lies outside the viewport, with the part of its footprint
  // inside: a viewport wider than the image by the largest point's radius keeps them (the
  // image itself clips the fragments). Without it magnified pictures had a ragged dark frame.
  const Projection image = scaledProjection(frame_.proj, frame_.splatScale);
  const int guard = guardBand(image);
  glViewport(-guard, -guard, image.width + 2 * guard, image.height + 2 * guard);
  drawSplatPrimitives(slab, quads, slabIndex);
  glViewport(0, 0, frame_.width, frame_.height);
}

void SplatRenderer::drawSplatPrimitives(const Slab& slab, bool quads, int slabIndex) {
  if (slabIndex >= 0) {
    // The counts are on the GPU: its commands draw them (bound by bindFrameState).
    const auto command = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    glUseProgram(splatPrograms_.point().id());
    glDrawArraysIndirect(GL_POINTS, command(gpuPartition_->pointCommand(size_t(slabIndex))));
    if (quads) {
      glUseProgram(splatPrograms_.quad().id());
      glDrawArraysIndirect(GL_TRIANGLE_STRIP,
                           command(gpuPartition_->quadCommand(size_t(slabIndex))));
    }
    return;
  }
  drawOrderRange(GL_POINTS, false, slab.first, slab.count);
  if (quads) drawOrderRange(GL_TRIANGLE_STRIP, true, slab.first, slab.count);
  stats_.slabEntries += slab.count;
}

void SplatRenderer::drawOrderRange(GLenum mode, bool instanced, size_t first, size_t count) {
  gl::Program& program = instanced ? splatPrograms_.quad() : splatPrograms_.point();
  glUseProgram(program.id());
  // Bound from the draw's first entry (rounded down to the binding alignment), so a list
  // larger than a storage block is drawn through windows of it, and the CPU's list, held in
  // pages, a page at most a draw.
  // Entries a binding holds; the rounding skips fewer than an alignment's worth.
  const uint64_t window = (storageBlockBytes() - storageAlignment_) / sizeof(uint32_t);
  // The GPU partition's list once its counts are read back (budgeted steps), else the CPU's.
  const bool gpuList = frame_.gpuSlabs;
  while (count > 0) {
    const OrderPages::Span page = gpuList
                                      ? OrderPages::Span{&gpuPartition_->orderBuffer(), 0, SIZE_MAX}
                                      : orderPages_.span(first);
    const uint64_t inPage = first - page.first;
    const uint64_t bytes = inPage * sizeof(uint32_t);
    const uint64_t offset = bytes - bytes % storageAlignment_;
    const uint64_t skip = (bytes - offset) / sizeof(uint32_t);
    const size_t n = size_t(std::min<uint64_t>({count, window - skip, page.count - inPage}));
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, page.buffer->id(), GLintptr(offset),
                      GLsizeiptr((skip + n) * sizeof(uint32_t)));
    program.setUInt("uFirst", uint32_t(skip));
    if (instanced)
      glDrawArraysInstanced(mode, 0, 4, GLsizei(n));
    else
      glDrawArrays(mode, 0, GLsizei(n));
    first += n;
    count -= n;
  }
}

Image8 SplatRenderer::readImage() const {
  Image8 img;
  img.width = targets_.width;
  img.height = targets_.height;
  img.channels = 3;
  std::vector<uint8_t> rgba(size_t(img.width) * img.height * 4);
  if (rgba.empty()) return img;
  targets_.output.getImage(0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  img.pixels.resize(size_t(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* src = rgba.data() + size_t(img.height - 1 - y) * img.width * 4;
    uint8_t* dst = img.pixels.data() + size_t(y) * img.width * 3;
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
  }
  return img;
}

std::vector<float> SplatRenderer::readOpticalDepth() const {
  std::vector<float> rgba(size_t(targets_.width) * targets_.height * 4);
  if (rgba.empty()) return {};
  targets_.slab.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  std::vector<float> depth(rgba.size() / 4);
  for (size_t p = 0; p < depth.size(); ++p) depth[p] = rgba[p * 4 + 3];
  return depth;
}

}  // namespace ewa

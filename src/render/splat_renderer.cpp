// SplatRenderer: its GL objects, classification into splats and their upload, splat drawing
// and read-back.
#include "render/splat_renderer.h"

#include <unistd.h>

#include <algorithm>
#include <string>

#include "core/named_values.h"
#include "gl/gl_error.h"
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
               pairTable_.bytes() + (tiles_ ? tiles_->bytes() : 0) + (cpu_ ? cpu_->bytes() : 0) +
               gradients_.bytes();
  return s;
}

void SplatRenderer::setPointSizeLimit(float limit) {
  pointSizeLimit_ = std::clamp(limit, 1.0f, glPointSizeLimit_);
}

void SplatRenderer::setVolume(const Volume& volume) {
  cancelCpu();      // it reads the splats and gradients
  upload_.reset();  // another volume's set
  volume_ = &volume;
  gradients_.invalidate();
  splatsDirty_ = true;
  passTuner_.reset();  // another volume: both ways timed again
  splatterTuner_.reset();
}

void SplatRenderer::setTransferFunction(const TransferFunction& tf) {
  upload_.reset();  // the function before's set
  tf_ = tf;
  splatsDirty_ = true;
}

void SplatRenderer::rebuildSplats(const Classification& classification) {
  splatsDirty_ = false;
  classification_ = classification;
  upload_.reset();
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
  cancelCpu();  // it reads the tables
  const double lo = volume_->minValue(), hi = volume_->maxValue();
  transferTable_ = tf_.bake(lo, hi, kTransferSamples);
  transferTexture_.subImage1D(0, 0, kTransferSamples, GL_RGBA, GL_FLOAT, transferTable_.data());
  pairTable_.invalidate();
}

void SplatRenderer::updateTransferTexture(const TransferFunction& tf) {
  tf_ = tf;
  if (volume_) uploadTransferTexture();
}

void SplatRenderer::setSplats(ClassifiedSplats splats, const Classification& classification) {
  upload_.reset();
  waitForPartition();  // the worker reads the splats being replaced
  classified_ = std::move(splats);
  classification_ = classification;
  splatsDirty_ = false;
  uploadSplats();
}

bool SplatRenderer::beginSplats(ClassifiedSplats splats, const Classification& classification) {
  if (!uploads_ || splats.splats.size() * sizeof(PackedSplat) < workerUploadBytes_) {
    setSplats(std::move(splats), classification);
    return true;
  }
  checkSplatCount(splats.splats.size());
  upload_.reset();  // waits for an upload under way
  upload_ = std::make_unique<SplatUpload>(std::move(splats), classification, *uploads_);
  return false;
}

bool SplatRenderer::takeUploadedSplats() {
  if (!upload_ || !upload_->done()) return false;
  installUpload();
  return true;
}

void SplatRenderer::installUpload() {
  std::unique_ptr<SplatUpload> upload = std::move(upload_);
  waitForPartition();  // the worker reads the splats being replaced
  ClassifiedSplats splats;
  gl::Buffer buffer;
  upload->finish(&splats, &buffer);  // the set before stays when the upload failed
  classified_ = std::move(splats);
  splatBuffer_ = std::move(buffer);
  classification_ = upload->classification();
  splatsDirty_ = false;
  splatBufferReplaced();
}

void SplatRenderer::checkSplatCount(size_t count) {
  // Order entries keep two flag bits above the splat index.
  if (count > SlabPartition::kIndexMask)
    throw gl::GlError("volume: more than 2^30 visible voxels: not supported by splatting");
}

void SplatRenderer::splatBufferReplaced() {
  // The order list's store is kept between frames (takeCpuPartition); a new splat set starts
  // it afresh, so a small volume after a big one does not hold the big one's store.
  if (!frame_.active) orderPages_.clear();
  attributesUploaded_ = false;  // the next frame uploads them if it needs them
}

void SplatRenderer::uploadSplats() {
  try {
    checkSplatCount(classified_.splats.size());
  } catch (const gl::GlError&) {
    classified_ = ClassifiedSplats{};
    splatsDirty_ = true;
    throw;
  }
  const size_t n = std::max<size_t>(1, classified_.splats.size());
  const auto& splats = classified_.splats.splats();
  splatBuffer_.setData(GLsizeiptr(n * sizeof(PackedSplat)),
                       splats.empty() ? nullptr : splats.data(), GL_STATIC_DRAW);
  // GL_OUT_OF_MEMORY here names the buffer instead of surfacing at the end of the frame.
  gl::checkGlError(("splat buffer upload (" + std::to_string(n) + " splats)").c_str());
  splatBufferReplaced();
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
  img.width = targets_.shownWidth();
  img.height = targets_.shownHeight();
  img.channels = 3;
  if (!targets_.shownOutput()) return Image8{};  // nothing finished yet
  std::vector<uint8_t> rgba(size_t(img.width) * img.height * 4);
  if (rgba.empty()) return img;
  targets_.shownOutput().getImage(0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  img.pixels.resize(size_t(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* src = rgba.data() + size_t(img.height - 1 - y) * img.width * 4;
    uint8_t* dst = img.pixels.data() + size_t(y) * img.width * 3;
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
  }
  return img;
}

std::vector<float> SplatRenderer::readFramePicture() const {
  const bool composite = frame_.settings.mode == RenderMode::Composite;
  // As drawFinalPass binds them (X-ray and MIP drawn on the CPU: the CPU's picture).
  const gl::Texture& picture = !composite ? (frame_.cpu ? cpu_->pictureTexture() : targets_.slab)
                               : frame_.tiles ? tiles_->pictureTexture()
                               : frame_.cpu   ? cpu_->pictureTexture()
                                              : targets_.accum;
  if (!picture) return {};
  std::vector<float> rgba(size_t(picture.width()) * size_t(picture.height()) * 4);
  if (rgba.empty()) return {};
  picture.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  return rgba;
}

std::vector<float> SplatRenderer::readOpticalDepth() const {
  if (frame_.cpu) {  // the CPU splatter's picture holds it
    const std::vector<glm::vec4>& picture = cpu_->picture();
    std::vector<float> depth(picture.size());
    for (size_t p = 0; p < depth.size(); ++p) depth[p] = picture[p].a;
    return depth;
  }
  std::vector<float> rgba(size_t(targets_.width) * targets_.height * 4);
  if (rgba.empty() || !targets_.slab) return {};
  targets_.slab.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  std::vector<float> depth(rgba.size() / 4);
  for (size_t p = 0; p < depth.size(); ++p) depth[p] = rgba[p * 4 + 3];
  return depth;
}

}  // namespace ewa

// TileEwaSplatter: the passes of shaders/tile_ewa.comp.glsl, timed with glFinish.
#include "render/tile_ewa_splatter.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "core/stopwatch.h"
#include "gl/gl_error.h"
#include "render/gl_limits.h"

namespace ewa {

namespace {

template <typename T>
void upload(gl::Buffer& buffer, const std::vector<T>& data) {
  buffer.setData(GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(T)),
                 data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
}

}  // namespace

TileEwaSplatter::TileEwaSplatter(const gl::ShaderLibrary& shaders, int tileSize)
    : TileEwaSplatter(std::make_shared<TileEwaPrograms>(shaders, tileSize)) {}

TileEwaSplatter::TileEwaSplatter(std::shared_ptr<TileEwaPrograms> programs)
    : programs_(std::move(programs)), chunkIterations_(softwareRasterizer() ? 60000 : 0) {}

void TileEwaSplatter::setFrame(const TileEwaFrame& frame) {
  // None given: the records are written on the GPU (reserveSplats, then the renderer's pass).
  if (!frame.splats.empty()) upload(splats_, frame.splats);
  upload(entries_, frame.entries);
  upload(slabs_, frame.slabDepths);
  entryCount_ = frame.entries.size();
  slabCount_ = frame.slabDepths.size();
  settings_.cutoff = frame.cutoff;
  settings_.depthProfile = frame.depthProfile;
  settings_.termination = frame.termination;
  settings_.post = frame.post;
  settings_.shading = frame.shading;
  settings_.rayNormals = frame.rayNormals;
  gpuLists_ = nullptr;
  slabEntries_.assign(slabCount_, 0);
  for (const glm::uvec2& entry : frame.entries)
    if (entry.y < slabCount_) ++slabEntries_[entry.y];
}

void TileEwaSplatter::useGpuSlabLists(const GpuSlabPartition& partition) {
  std::vector<glm::vec2> depths;
  for (const Slab& slab : partition.slabs())
    depths.emplace_back(float(slab.nearDepth), float(slab.farDepth));
  upload(slabs_, depths);
  slabCount_ = depths.size();
  entryCount_ = partition.entryCount();
  gpuLists_ = &partition;
  slabEntries_.clear();
  if (partition.countsKnown())
    for (const Slab& slab : partition.slabs()) slabEntries_.push_back(slab.count);
}

std::vector<glm::uvec2> TileEwaSplatter::compositeChunks() const {
  const auto slabs = GLuint(slabCount_);
  if (chunkIterations_ == 0 || slabEntries_.size() != slabCount_) return {glm::uvec2(0, slabs)};
  // A tile's iterations in a slab: at most its entries over eight (the splats an iteration)
  // and over the smallest batch, and about a dozen more (the batches, the classification's
  // loops); bounded by the slab's entries, every tile's at once.
  std::vector<glm::uvec2> chunks;
  size_t iterations = 0;
  GLuint first = 0;
  for (GLuint b = 0; b < slabs; ++b) {
    const size_t cost = 12 + slabEntries_[b] / 8 + slabEntries_[b] / 64;
    if (b > first && iterations + cost > chunkIterations_) {
      chunks.emplace_back(first, b);
      first = b;
      iterations = 0;
    }
    iterations += cost;
  }
  chunks.emplace_back(first, slabs);
  return chunks;
}

void TileEwaSplatter::reserveSplats(size_t count) {
  splats_.reserve(GLsizeiptr(std::max<size_t>(1, count) * sizeof(TileEwaSplat)),
                  "tile EWA splat records");
}

gl::Program& TileEwaSplatter::compositeProgram() {
  return programs_->composite(settings_.post, settings_.shading, settings_.rayNormals);
}

TileEwaSplatter::Timing TileEwaSplatter::draw(int width, int height) {
  if (picture_.width() != width || picture_.height() != height)
    picture_ = gl::Texture::create2D(GL_RGBA32F, width, height);
  const int side = programs_->tileSize();
  const glm::ivec2 tiles((width + side - 1) / side, (height + side - 1) / side);
  const size_t slabs = std::max<size_t>(1, slabCount_);
  const size_t buckets = size_t(tiles.x) * size_t(tiles.y) * slabs;
  gl::Program& composite = compositeProgram();
  gl::Program& count = programs_->count(gpuLists_ != nullptr);
  gl::Program& scatter = programs_->scatter(gpuLists_ != nullptr);
  gl::Program& scan = programs_->scan();
  const bool fieldNormals = settings_.post && settings_.shading && !settings_.rayNormals;
  for (gl::Program* p : {&count, &scatter, &composite}) {
    p->setUInt("uCount", GLuint(entryCount_));
    p->setUInt("uSlabCount", GLuint(slabCount_));
    p->setIVec2("uTiles", tiles);
    p->setIVec2("uViewport", glm::ivec2(width, height));
    p->setFloat("uCutoff", settings_.cutoff);
    p->setVec2("uDepthProfile", settings_.depthProfile);
    p->setFloat("uTermination", settings_.termination);
    // Post-classified tiles shaded from the field's gradient read their border's pixels.
    p->setFloat("uBorder", fieldNormals ? 1.0f : 0.0f);
  }
  // The scan sees the buckets as one row of "tiles".
  scan.setIVec2("uTiles", glm::ivec2(int(buckets), 1));
  splats_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  if (gpuLists_) {
    gpuLists_->orderBuffer().bindBase(GL_SHADER_STORAGE_BUFFER, 3);
    gpuLists_->firstBuffer().bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  } else {
    entries_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  }
  slabs_.bindBase(GL_SHADER_STORAGE_BUFFER, 5);

  Timing t;
  glFinish();
  auto start = std::chrono::steady_clock::now();
  t.entries = bins_.bin(count, scan, scatter, entryCount_, buckets, 4);
  glFinish();
  t.binMs = millisecondsSince(start);

  start = std::chrono::steady_clock::now();
  const std::vector<glm::uvec2> chunks = compositeChunks();
  if (settings_.post && chunks.size() > 1 &&
      (lastFront_.width() != width || lastFront_.height() != height)) {
    lastFront_ = gl::Texture::create2D(GL_RGBA32F, width, height);
    lastBack_ = gl::Texture::create2D(GL_RGBA32F, width, height);
  }
  glBindImageTexture(0, picture_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  if (settings_.post && chunks.size() > 1) {
    glBindImageTexture(1, lastFront_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(2, lastBack_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  }
  glUseProgram(composite.id());
  for (const glm::uvec2& chunk : chunks) {
    composite.setUInt("uSlabBegin", chunk.x);
    composite.setUInt("uSlabEnd", chunk.y);
    glDispatchCompute(GLuint(tiles.x), GLuint(tiles.y), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  t.chunks = chunks.size();
  glFinish();
  t.compositeMs = millisecondsSince(start);
  gl::checkGlError("tile EWA draw");
  return t;
}

size_t TileEwaSplatter::bytes() const {
  const size_t images = size_t(picture_.width()) * size_t(picture_.height()) +
                        2 * size_t(lastFront_.width()) * size_t(lastFront_.height());
  return size_t(splats_.size() + entries_.size() + slabs_.size()) + bins_.bytes() +
         images * sizeof(glm::vec4);
}

std::vector<glm::vec4> TileEwaSplatter::picture() const {
  std::vector<glm::vec4> out(size_t(picture_.width()) * size_t(picture_.height()));
  picture_.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)), out.data());
  return out;
}

}  // namespace ewa

// TileEwaSplatter: the passes of shaders/tile_ewa.comp.glsl, timed with glFinish.
#include "render/tile_ewa_splatter.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "core/stopwatch.h"
#include "gl/gl_error.h"

namespace ewa {

namespace {

std::string defines(int tileSize, const char* pass) {
  return "#define TILE_SIZE " + std::to_string(tileSize) + "\n#define " + pass + " 1\n";
}

template <typename T>
void upload(gl::Buffer& buffer, const std::vector<T>& data) {
  buffer.setData(GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(T)),
                 data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
}

}  // namespace

TileEwaSplatter::TileEwaSplatter(const gl::ShaderLibrary& shaders, int tileSize)
    : tileSize_(tileSize),
      countPass_(shaders.computeProgram("tile_ewa.comp.glsl", defines(tileSize, "COUNT_PASS"))),
      // The scan of tile_splat.comp.glsl, over (tile, slab) buckets in place of tiles.
      scanPass_(shaders.computeProgram(
          "tile_splat.comp.glsl",
          defines(tileSize, "SCAN_PASS") + "#define IMAGE_FORMAT rgba32f\n")),
      scatterPass_(shaders.computeProgram("tile_ewa.comp.glsl", defines(tileSize, "SCATTER_PASS"))),
      compositePass_(
          shaders.computeProgram("tile_ewa.comp.glsl", defines(tileSize, "COMPOSITE_PASS"))) {}

void TileEwaSplatter::setFrame(const TileEwaFrame& frame) {
  upload(splats_, frame.splats);
  upload(entries_, frame.entries);
  upload(slabs_, frame.slabDepths);
  entryCount_ = frame.entries.size();
  slabCount_ = frame.slabDepths.size();
  settings_.cutoff = frame.cutoff;
  settings_.depthProfile = frame.depthProfile;
  settings_.termination = frame.termination;
}

TileEwaSplatter::Timing TileEwaSplatter::draw(int width, int height) {
  if (picture_.width() != width || picture_.height() != height)
    picture_ = gl::Texture::create2D(GL_RGBA32F, width, height);
  const glm::ivec2 tiles((width + tileSize_ - 1) / tileSize_, (height + tileSize_ - 1) / tileSize_);
  const size_t slabs = std::max<size_t>(1, slabCount_);
  const size_t buckets = size_t(tiles.x) * size_t(tiles.y) * slabs;
  for (gl::Program* p : {&countPass_, &scatterPass_, &compositePass_}) {
    p->setUInt("uCount", GLuint(entryCount_));
    p->setUInt("uSlabCount", GLuint(slabCount_));
    p->setIVec2("uTiles", tiles);
    p->setIVec2("uViewport", glm::ivec2(width, height));
    p->setFloat("uCutoff", settings_.cutoff);
    p->setVec2("uDepthProfile", settings_.depthProfile);
    p->setFloat("uTermination", settings_.termination);
  }
  // The scan sees the buckets as one row of "tiles".
  scanPass_.setIVec2("uTiles", glm::ivec2(int(buckets), 1));
  splats_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  entries_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  slabs_.bindBase(GL_SHADER_STORAGE_BUFFER, 5);

  Timing t;
  glFinish();
  auto start = std::chrono::steady_clock::now();
  t.entries = bins_.bin(countPass_, scanPass_, scatterPass_, entryCount_, buckets, 4);
  glFinish();
  t.binMs = millisecondsSince(start);

  start = std::chrono::steady_clock::now();
  glBindImageTexture(0, picture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glUseProgram(compositePass_.id());
  glDispatchCompute(GLuint(tiles.x), GLuint(tiles.y), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glFinish();
  t.compositeMs = millisecondsSince(start);
  gl::checkGlError("tile EWA draw");
  return t;
}

std::vector<glm::vec4> TileEwaSplatter::picture() const {
  std::vector<glm::vec4> out(size_t(picture_.width()) * size_t(picture_.height()));
  picture_.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)), out.data());
  return out;
}

}  // namespace ewa

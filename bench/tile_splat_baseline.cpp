// TileSplatBaseline: the four passes of shaders/tile_splat.comp.glsl, timed with glFinish.
#include "bench/tile_splat_baseline.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "core/stopwatch.h"
#include "gl/gl_error.h"

namespace ewa {

namespace {

std::string defines(int tileSize, const char* pass, const char* format = "rgba32f") {
  return "#define TILE_SIZE " + std::to_string(tileSize) + "\n#define " + pass +
         " 1\n#define IMAGE_FORMAT " + format + "\n";
}

}  // namespace

TileSplatBaseline::TileSplatBaseline(const gl::ShaderLibrary& shaders, int tileSize)
    : tileSize_(tileSize),
      countPass_(shaders.computeProgram("tile_splat.comp.glsl", defines(tileSize, "COUNT_PASS"))),
      scanPass_(shaders.computeProgram("tile_splat.comp.glsl", defines(tileSize, "SCAN_PASS"))),
      scatterPass_(
          shaders.computeProgram("tile_splat.comp.glsl", defines(tileSize, "SCATTER_PASS"))),
      accumulateHalf_(shaders.computeProgram("tile_splat.comp.glsl",
                                             defines(tileSize, "ACCUMULATE_PASS", "rgba16f"))),
      accumulateFloat_(
          shaders.computeProgram("tile_splat.comp.glsl", defines(tileSize, "ACCUMULATE_PASS"))) {}

void TileSplatBaseline::setFootprints(const std::vector<TileFootprint>& footprints, float cutoff) {
  count_ = footprints.size();
  cutoff_ = cutoff;
  footprints_.setData(GLsizeiptr(std::max<size_t>(1, count_) * sizeof(TileFootprint)),
                      count_ ? footprints.data() : nullptr, GL_STATIC_DRAW);
}

TileSplatBaseline::Timing TileSplatBaseline::draw(int width, int height, bool halfFloat) {
  const GLenum format = halfFloat ? GL_RGBA16F : GL_RGBA32F;
  if (front_.width() != width || front_.height() != height || front_.internalFormat() != format) {
    front_ = gl::Texture::create2D(format, width, height);
    back_ = gl::Texture::create2D(format, width, height);
  }
  const glm::ivec2 tiles((width + tileSize_ - 1) / tileSize_, (height + tileSize_ - 1) / tileSize_);
  const size_t tileCount = size_t(tiles.x) * size_t(tiles.y);
  for (gl::Program* p :
       {&countPass_, &scanPass_, &scatterPass_, &accumulateHalf_, &accumulateFloat_}) {
    p->setUInt("uCount", GLuint(count_));
    p->setIVec2("uTiles", tiles);
    p->setIVec2("uViewport", glm::ivec2(width, height));
    p->setFloat("uCutoff", cutoff_);
  }
  footprints_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);

  Timing t;
  glFinish();
  auto start = std::chrono::steady_clock::now();
  t.entries = bins_.bin(countPass_, scanPass_, scatterPass_, count_, tileCount, 3);
  glFinish();
  t.binMs = millisecondsSince(start);

  start = std::chrono::steady_clock::now();
  glBindImageTexture(0, front_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glBindImageTexture(1, back_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glUseProgram((halfFloat ? accumulateHalf_ : accumulateFloat_).id());
  glDispatchCompute(GLuint(tiles.x), GLuint(tiles.y), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glFinish();
  t.accumulateMs = millisecondsSince(start);
  gl::checkGlError("tile splat draw");
  return t;
}

std::vector<glm::vec4> TileSplatBaseline::frontImage() const {
  std::vector<glm::vec4> out(size_t(front_.width()) * size_t(front_.height()));
  front_.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)), out.data());
  return out;
}

}  // namespace ewa

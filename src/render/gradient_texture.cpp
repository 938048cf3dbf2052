// GradientTexture: packs the volume's gradient on a worker and uploads it as an RGB10_A2 3D
// texture, or keeps it in memory, or both.
#include "render/gradient_texture.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "gl/gl_error.h"

namespace ewa {

GradientTexture::~GradientTexture() {
  invalidate();  // the worker reads the volume
}

void GradientTexture::checkTextureSize(const Volume& volume) {
  const auto& d = volume.dims();
  GLint largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  if (std::max({d[0], d[1], d[2]}) > int64_t(largest))
    throw gl::GlError("volume: " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
                      std::to_string(d[2]) + " voxels exceed GL_MAX_3D_TEXTURE_SIZE " +
                      std::to_string(largest) +
                      " for the ray normals' gradient texture (--post-normals field does not "
                      "need it)");
}

void GradientTexture::request(const Volume& volume, GradientMode mode, GradientUse use) {
  const bool texture = use == GradientUse::Texture;
  if (texture) checkTextureSize(volume);
  use_ = use;
  if (volume_ == &volume && mode_ == mode) {  // held, or under way, for a use
    if (texture && !wantTexture_) {
      wantTexture_ = true;
      if (!pending_.valid()) beginUpload();  // from the gradients held in memory
    }
    if (!texture && !keepPacked_) {
      keepPacked_ = true;
      // The texture's upload under way keeps its copy; a texture held alone is packed again.
      if (!pending_.valid() && !uploading_)
        pending_ =
            std::async(std::launch::async, [&volume, mode] { return packGradients(volume, mode); });
    }
    return;
  }
  release();  // other gradients
  volume_ = &volume;
  mode_ = mode;
  wantTexture_ = texture;
  keepPacked_ = !texture;
  pending_ =
      std::async(std::launch::async, [&volume, mode] { return packGradients(volume, mode); });
}

void GradientTexture::beginUpload() {
  const auto& d = packed_.dims;
  texture_ = gl::Texture();
  texture_ = gl::Texture::create3D(GL_RGB10_A2, GLsizei(d[0]), GLsizei(d[1]), GLsizei(d[2]));
  gl::checkGlError(
      ("gradient texture (" + std::to_string(d[0] * d[1] * d[2]) + " voxels)").c_str());
  uploaded_ = 0;
  uploading_ = true;
}

bool GradientTexture::ready(double budgetMs) {
  const auto start = std::chrono::steady_clock::now();
  if (volume_ == nullptr) return false;
  if (pending_.valid()) {
    if (std::isfinite(budgetMs)) {
      const auto wait = std::chrono::duration<double, std::milli>(std::max(budgetMs, 0.0));
      if (pending_.wait_for(wait) != std::future_status::ready) return false;
    }
    packed_ = pending_.get();
    if (wantTexture_ && !texture_) beginUpload();
  }
  if (uploading_) {
    if (!uploadParts(budgetMs, start)) return false;
    uploading_ = false;
    if (!keepPacked_) packed_ = PackedGradients();
  }
  return holds(*volume_, mode_, use_);
}

bool GradientTexture::uploadParts(double budgetMs, std::chrono::steady_clock::time_point start) {
  const auto& d = packed_.dims;
  // Parts of about 4 MB: small beside a step's budget even on llvmpipe, and a small staging copy.
  const int64_t slice = d[0] * d[1];
  const int64_t step = std::max<int64_t>(1, (int64_t(4) << 20) / (4 * slice));
  while (uploaded_ < d[2]) {
    const int64_t n = std::min(step, d[2] - uploaded_);
    texture_.subImage3D(0, 0, 0, GLint(uploaded_), GLsizei(d[0]), GLsizei(d[1]), GLsizei(n),
                        GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV,
                        packed_.texels.data() + uploaded_ * slice);
    uploaded_ += n;
    if (uploaded_ < d[2] && std::isfinite(budgetMs) &&
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count() >= budgetMs)
      return false;
  }
  gl::checkGlError(
      ("gradient texture upload (" + std::to_string(d[0] * d[1] * d[2]) + " voxels)").c_str());
  return true;
}

void GradientTexture::invalidate() {
  if (pending_.valid()) pending_.wait();
  pending_ = {};
  uploading_ = false;
  packed_ = PackedGradients();
  volume_ = nullptr;
  wantTexture_ = keepPacked_ = false;
}

void GradientTexture::releaseWhenIdle() {
  if (pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  release();
}

void GradientTexture::release() {
  invalidate();
  texture_ = gl::Texture();
}

void GradientTexture::bindUnit(unsigned unit) const {
  if (texture_) {
    texture_.bindUnit(unit);
  } else {
    glBindTextureUnit(unit, 0);
  }
}

size_t GradientTexture::bytes() const {
  return texture_
             ? size_t(texture_.width()) * size_t(texture_.height()) * size_t(texture_.depth()) * 4
             : 0;
}

}  // namespace ewa

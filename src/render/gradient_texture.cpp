// GradientTexture: packs the volume's gradient on a worker and uploads it as an RGB10_A2 3D
// texture.
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

void GradientTexture::request(const Volume& volume, GradientMode mode) {
  if (holds(volume, mode)) return;
  if (pending_.valid() && pendingVolume_ == &volume && pendingMode_ == mode) return;
  invalidate();
  const auto& d = volume.dims();
  GLint largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  if (std::max({d[0], d[1], d[2]}) > int64_t(largest))
    throw gl::GlError("volume: " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
                      std::to_string(d[2]) + " voxels exceed GL_MAX_3D_TEXTURE_SIZE " +
                      std::to_string(largest) +
                      " for the ray normals' gradient texture (--post-normals field does not "
                      "need it)");
  pendingVolume_ = &volume;
  pendingMode_ = mode;
  pending_ =
      std::async(std::launch::async, [&volume, mode] { return packGradients(volume, mode); });
}

bool GradientTexture::ready(double waitMs) {
  if (!pending_.valid()) return texture_ && volume_ != nullptr;
  if (std::isfinite(waitMs)) {
    const auto wait = std::chrono::duration<double, std::milli>(std::max(waitMs, 0.0));
    if (pending_.wait_for(wait) != std::future_status::ready) return false;
  }
  const PackedGradients packed = pending_.get();
  const Volume* volume = pendingVolume_;
  pendingVolume_ = nullptr;
  upload(packed);
  volume_ = volume;
  mode_ = pendingMode_;
  return true;
}

void GradientTexture::upload(const PackedGradients& packed) {
  texture_ = gl::Texture();
  volume_ = nullptr;
  const auto& d = packed.dims;
  texture_ = gl::Texture::create3D(GL_RGB10_A2, GLsizei(d[0]), GLsizei(d[1]), GLsizei(d[2]));
  // In parts of at most 64 MB, so the driver's staging copy stays small for big volumes.
  const int64_t slice = d[0] * d[1];
  const int64_t step = std::max<int64_t>(1, (int64_t(64) << 20) / (4 * slice));
  for (int64_t z = 0; z < d[2]; z += step) {
    const int64_t n = std::min(step, d[2] - z);
    texture_.subImage3D(0, 0, 0, GLint(z), GLsizei(d[0]), GLsizei(d[1]), GLsizei(n), GL_RGBA,
                        GL_UNSIGNED_INT_2_10_10_10_REV, packed.texels.data() + z * slice);
  }
  gl::checkGlError(
      ("gradient texture upload (" + std::to_string(d[0] * d[1] * d[2]) + " voxels)").c_str());
}

void GradientTexture::invalidate() {
  if (pending_.valid()) pending_.wait();
  pending_ = {};
  pendingVolume_ = nullptr;
  volume_ = nullptr;
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

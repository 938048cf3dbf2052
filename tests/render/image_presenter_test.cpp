// ImagePresenter: the window's copy of the picture to the default framebuffer, exact at the
// same size and stretched otherwise; the exact copy's warm-up (made at the first stretch) leaves
// no trace.
#include "ui/image_presenter.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "gl/gl_api.h"
#include "gl/texture.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class ImagePresenterTest : public RenderFixture {};

constexpr int kFb = 16;  // the fixture's default framebuffer (createHeadlessContext(.., 16, 16))

// An RGBA8 texture whose texel (x, y) is (x * step, y * step, 40, 255).
gl::Texture gradientTexture(int size, int step) {
  std::vector<uint8_t> texels(size_t(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      uint8_t* t = &texels[(size_t(y) * size + x) * 4];
      t[0] = uint8_t(x * step);
      t[1] = uint8_t(y * step);
      t[2] = 40;
      t[3] = 255;
    }
  gl::Texture texture = gl::Texture::create2D(GL_RGBA8, size, size);
  texture.subImage2D(0, 0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  return texture;
}

std::vector<uint8_t> readDefaultFramebuffer() {
  std::vector<uint8_t> pixels(size_t(kFb) * kFb * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kFb, kFb, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

TEST_F(ImagePresenterTest, CopiesExactlyAndStretchesWithoutTheWarmUpsPixel) {
  if (glCheckNamedFramebufferStatus(0, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    GTEST_SKIP() << "this context has no default framebuffer";
  ImagePresenter presenter;
  // A picture of another size (here 32x32 texels, minified, so that each pixel is the mean of
  // four texels and differs from the warm-up's copied texel): the warm-up copies one texel to
  // pixel (0, 0) first, the stretch must cover it.
  const gl::Texture other = gradientTexture(32, 8);
  presenter.present(other.id(), 32, 32, kFb, kFb);
  const std::vector<uint8_t> first = readDefaultFramebuffer();
  presenter.present(other.id(), 32, 32, kFb, kFb);  // warmed up already: the stretch alone
  EXPECT_EQ(readDefaultFramebuffer(), first);
  // Bilinear: pixel x's centre lies between texels 2x and 2x + 1, red 8 * (2x + 0.5).
  for (int y = 0; y < kFb; ++y)
    for (int x = 0; x < kFb; ++x) {
      const uint8_t* p = &first[(size_t(y) * kFb + x) * 4];
      ASSERT_NEAR(p[0], 16.0 * x + 4.0, 1.0) << x << "," << y;
      ASSERT_NEAR(p[1], 16.0 * y + 4.0, 1.0) << x << "," << y;
    }
  // The full picture at the window's size: an exact copy.
  const gl::Texture full = gradientTexture(kFb, 15);
  presenter.present(full.id(), kFb, kFb, kFb, kFb);
  const std::vector<uint8_t> exact = readDefaultFramebuffer();
  for (int y = 0; y < kFb; ++y)
    for (int x = 0; x < kFb; ++x) {
      const uint8_t* p = &exact[(size_t(y) * kFb + x) * 4];
      ASSERT_EQ(int(p[0]), x * 15) << x << "," << y;
      ASSERT_EQ(int(p[1]), y * 15) << x << "," << y;
      ASSERT_EQ(int(p[2]), 40);
    }
}

}  // namespace
}  // namespace ewa::test

// Shaded post-classification with ray normals: smooth surfaces seen obliquely stay smooth where
// the field's gradient shows the slab period as stripes; the gradients held for both splatters.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "image_compare.h"
#include "render/gradient_texture.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class RayNormals : public RenderFixture {};

// Mean absolute second difference of the red channel down the columns and along the rows of the
// `side` x `side` pixels about the centre: near 0 for a flat surface lit smoothly, large where
// the shading steps at every slab.
double stripeEnergy(const Image8& img, int side) {
  auto at = [&](int x, int y) { return double(img.pixels[(size_t(y) * img.width + x) * 3]); };
  const int x0 = (img.width - side) / 2, y0 = (img.height - side) / 2;
  double sum = 0.0;
  int n = 0;
  for (int y = y0 + 1; y < y0 + side - 1; ++y)
    for (int x = x0 + 1; x < x0 + side - 1; ++x) {
      sum += std::abs(at(x, y - 1) - 2.0 * at(x, y) + at(x, y + 1)) +
             std::abs(at(x - 1, y) - 2.0 * at(x, y) + at(x + 1, y));
      n += 2;
    }
  return sum / n;
}

// An opaque half-space whose tilted face crosses the slabs obliquely, seen in perspective with
// a head light: the face's brightness varies smoothly with its angle to each ray. Ray normals,
// the data's gradient read at each segment, keep it smooth; the field's gradient (its depth
// part a difference of the slab's halves, which swings with where the face lies in the slab)
// draws a stripe at every slab.
TEST_F(RayNormals, ObliqueFaceShowsNoSlabStripes) {
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
  const Volume half = floatVolume(48, [&](int i, int j, int k) {
    const double d = glm::dot(glm::dvec3(i, j, k) - glm::dvec3(23.5), normal);
    return float(1.0 / (1.0 + std::exp(2.0 * d)));  // 1 below the face, 0 above
  });
  renderer()->setVolume(half);
  renderer()->setTransferFunction(opaqueStepTf());
  Camera cam;
  cam.focalPoint = glm::dvec3(23.5);
  cam.position = glm::dvec3(23.5) + glm::dvec3(40.0, -25.0, 30.0);
  cam.viewUp = {0.0, 0.0, 1.0};
  RenderSettings settings;
  settings.lighting.enabled = true;
  settings.lighting.specular = 0.0;
  const int size = 128;
  double energy[3] = {0.0, 0.0, 0.0};
  Image8 pictures[3];
  for (PostNormals normals : {PostNormals::Field, PostNormals::Ray}) {
    settings.postNormals = normals;
    renderer()->render(cam, settings, size, size);
    const Image8 img = renderer()->readImage();
    EXPECT_GT(meanValue(img), 100.0) << "the face should fill the picture";
    energy[int(normals)] = stripeEnergy(img, 48);
    pictures[int(normals)] = img;
  }
  // Measured: field 2.46, ray 0.59 (a smooth ramp's 8-bit steps alone give about 0.5).
  const double ray = energy[int(PostNormals::Ray)], field = energy[int(PostNormals::Field)];
  EXPECT_LT(ray, 0.8);
  EXPECT_GT(field, 3.0 * ray) << "the field's stripes should show: is the test still seeing them?";
  if (HasFailure()) {
    for (PostNormals normals : {PostNormals::Field, PostNormals::Ray}) {
      const std::string out =
          testOutputDir() + "/ray_normals_" + postNormalsName(normals) + ".actual.png";
      writePng(out, pictures[int(normals)]);
      ADD_FAILURE() << "picture written to " << out;
    }
  }
}

// Spread of the red channel over the `side` x `side` pixels about the centre (largest less
// smallest).
int centreSpread(const Image8& img, int side) {
  int lo = 255, hi = 0;
  const int x0 = (img.width - side) / 2, y0 = (img.height - side) / 2;
  for (int y = y0; y < y0 + side; ++y)
    for (int x = x0; x < x0 + side; ++x) {
      const int v = img.pixels[(size_t(y) * img.width + x) * 3];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  return hi - lo;
}

// Uniform haze seen in parallel through two parallel faces: every central ray crosses the same
// haze, so the picture is one grey. Its gradient is zero; the field's, from sums of kernels in
// float, is rounding noise, which normalized would light each pixel at random (on a GPU, whose
// sums differ run to run, up to 125 levels between the rasterizer and the compute tiles).
// Gradients that small are no direction: those pixels are drawn unshaded, as zero ones are.
TEST_F(RayNormals, UniformHazeIsLitEvenlyWithEitherNormals) {
  const Volume haze = floatVolume(32, [](int i, int j, int k) {
    return i + j + k == 0 ? 0.0f : 1.0f;  // one empty corner voxel: a range to normalize by
  });
  renderer()->setVolume(haze);
  renderer()->setTransferFunction(whiteTf(0.02, 1.0));
  Camera cam;
  cam.orthographic = true;
  cam.frame(haze.boundsMin(), haze.boundsMax(), {0.12, -0.08, 1.0}, {0, 1, 0}, 1.0);
  cam.dolly(1.5);
  RenderSettings settings;
  settings.lighting.enabled = true;
  for (PostNormals normals : {PostNormals::Field, PostNormals::Ray}) {
    for (Splatter splatter : {Splatter::Raster, Splatter::Tiles}) {
      SCOPED_TRACE(std::string(postNormalsName(normals)) +
                   (splatter == Splatter::Tiles ? ", tiles" : ", raster"));
      settings.postNormals = normals;
      settings.splatter = splatter;
      renderer()->render(cam, settings, 64, 64);
      const Image8 img = renderer()->readImage();
      EXPECT_GT(meanValue(img), 40.0) << "the haze should show";
      EXPECT_LE(centreSpread(img, 24), 1);
    }
  }
}

// The gradient texture is packed on a worker: a budgeted frame on a volume just set steps
// without it until it is ready, then draws the picture a whole frame draws.
TEST_F(RayNormals, BudgetedFrameWaitsForTheGradientsInSteps) {
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:64");
  SplatRenderer& r = *renderer();
  r.setPartition(PartitionMode::Cpu);  // one order of sums: the same picture to the bit
  r.setVolume(s.volume);
  r.setTransferFunction(*s.transferFunction);
  Camera cam;
  cam.frame(s.volume.boundsMin(), s.volume.boundsMax(), {1.0, -0.4, 0.3}, {0, 0, 1}, 1.0);
  RenderSettings settings = rasterSettings();  // stepped slab by slab, its bytes counted
  settings.lighting.enabled = true;
  const int size = 64;
  r.render(cam, settings, size, size);
  const Image8 whole = r.readImage();
  EXPECT_GE(r.stats().gpuBytes, size_t(64 * 64 * 64 * 4)) << "the texture is held";
  r.setVolume(s.volume);  // the texture is built again
  r.beginFrame(cam, settings, size, size);
  int steps = 0;
  while (!r.stepFrame(1.0)) ASSERT_LT(++steps, 100000);
  EXPECT_GT(steps, 0);
  EXPECT_EQ(maxDifference(r.readImage(), whole), 0);
  // An unshaded frame frees the texture (nothing packs it now).
  const size_t shaded = r.stats().gpuBytes;
  settings.lighting.enabled = false;
  r.render(cam, settings, size, size);
  EXPECT_LE(r.stats().gpuBytes + size_t(64 * 64 * 64 * 4), shaded);
}

// The gradients for both splatters at once: kept in memory for the CPU splatter, a texture made
// from that copy for the slab pass (nothing packed again), and a texture held alone packed
// again into memory while the texture stays usable.
TEST_F(RayNormals, GradientsAreHeldForBothSplattersAtOnce) {
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:24");
  const double unlimited = std::numeric_limits<double>::infinity();
  const size_t texels = size_t(24 * 24 * 24);
  GradientTexture g;
  g.request(s.volume, GradientMode::Central, GradientUse::Memory);
  EXPECT_FALSE(g.holds(s.volume, GradientMode::Central, GradientUse::Memory));
  ASSERT_TRUE(g.ready(unlimited));
  ASSERT_EQ(g.packed().texels.size(), texels);
  EXPECT_EQ(g.bytes(), 0u) << "no texture";
  const PackedGradients copy = g.packed();
  const uint32_t* data = g.packed().texels.data();
  g.request(s.volume, GradientMode::Central, GradientUse::Texture);
  ASSERT_TRUE(g.ready(unlimited));
  EXPECT_TRUE(g.holds(s.volume, GradientMode::Central, GradientUse::Texture));
  EXPECT_TRUE(g.holds(s.volume, GradientMode::Central, GradientUse::Memory));
  EXPECT_EQ(g.packed().texels.data(), data) << "the same copy, not packed again";
  EXPECT_EQ(g.bytes(), texels * 4);
  // The texture holds what memory does.
  g.bindUnit(7);
  glActiveTexture(GL_TEXTURE7);
  GLint texture = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
  glActiveTexture(GL_TEXTURE0);
  std::vector<uint32_t> read(texels);
  glGetTextureImage(GLuint(texture), 0, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV,
                    GLsizei(read.size() * 4), read.data());
  EXPECT_EQ(read, copy.texels);
  // Texture alone (another mode), then memory: packed again, the texture held meanwhile.
  g.request(s.volume, GradientMode::Smooth, GradientUse::Texture);
  ASSERT_TRUE(g.ready(unlimited));
  EXPECT_TRUE(g.packed().texels.empty()) << "the upload's copy freed";
  g.request(s.volume, GradientMode::Smooth, GradientUse::Memory);
  EXPECT_TRUE(g.holds(s.volume, GradientMode::Smooth, GradientUse::Texture));
  ASSERT_TRUE(g.ready(unlimited));
  EXPECT_EQ(g.packed().texels, packGradients(s.volume, GradientMode::Smooth).texels);
  EXPECT_TRUE(g.holds(s.volume, GradientMode::Smooth, GradientUse::Texture));
}

}  // namespace
}  // namespace ewa::test

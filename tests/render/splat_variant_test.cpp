// Splat program variants: each frame compiles in only the paths its settings use (MIP, post,
// halves, clipping); switching between them must leave every picture as a fresh renderer draws it.
#include <cmath>
#include <set>

#include "render/splat_programs.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SplatVariants : public RenderFixture {};

TEST(SplatVariant, EveryCombinationHasItsOwnKeyAndDefines) {
  std::set<unsigned> keys;
  std::set<std::string> defines;
  for (unsigned bits = 0; bits < 16; ++bits) {
    SplatVariant v;
    v.mip = bits & 1;
    v.post = bits & 2;
    v.halves = bits & 4;
    v.clip = bits & 8;
    keys.insert(v.key());
    defines.insert(v.defines());
    EXPECT_NE(v.defines().find(std::string("#define SPLAT_CLIP ") + (v.clip ? "1" : "0")),
              std::string::npos);
  }
  EXPECT_EQ(keys.size(), 16u);
  EXPECT_EQ(defines.size(), 16u);
}

RenderSettings variantSettings(int which) {
  RenderSettings s;
  switch (which) {
    case 1:
      s.mode = RenderMode::Mip;
      break;
    case 2:
      s.classification.mode = ClassificationMode::Post;  // with pre-integration: halves
      break;
    case 3:
      s.classification.mode = ClassificationMode::Post;
      s.slabPreintegration = false;
      break;
    case 4:
      s.clip.cropEnabled = true;
      s.clip.cropMin = glm::dvec3(-100.0);
      s.clip.cropMax = glm::dvec3(100.0, 100.0, 14.3);
      break;
    default:
      break;
  }
  return s;
}

// One renderer drawing pre, MIP, post with and without halves, clipped and pre again, each
// twice, gives what a renderer that never drew anything else gives, bit for bit.
TEST_F(SplatVariants, SwitchingVariantsKeepsEveryPicture) {
  const Volume vol = floatVolume(24, [](int i, int j, int k) {
    return float(std::max(0.0, 10.0 - glm::length(glm::dvec3(i, j, k) - glm::dvec3(11.5))));
  });
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {4.0, 0.3}, {10.0, 0.9}};
  tf.color = {{0.0, glm::dvec3(0.2, 0.4, 1.0)}, {10.0, glm::dvec3(1.0, 0.8, 0.3)}};
  tf.opacityUnitDistance = 2.0;
  Camera cam;
  cam.focalPoint = glm::dvec3(11.5);
  cam.position = cam.focalPoint + glm::dvec3(20.0, 25.0, 60.0);
  const int size = 64;
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(tf);
  const int sequence[] = {0, 1, 2, 3, 4, 0, 4, 2, 1, 3};
  std::vector<std::vector<uint8_t>> first(5);
  for (int which : sequence) {
    renderer()->render(cam, variantSettings(which), size, size);
    const Image8 img = renderer()->readImage();
    if (first[which].empty()) {
      first[which] = img.pixels;
      const gl::ShaderLibrary shaders;
      SplatRenderer fresh(shaders);
      fresh.setVolume(vol);
      fresh.setTransferFunction(tf);
      fresh.render(cam, variantSettings(which), size, size);
      EXPECT_EQ(fresh.readImage().pixels, img.pixels) << "variant " << which;
    } else {
      EXPECT_EQ(first[which], img.pixels) << "variant " << which << " drawn again";
    }
  }
  // The variants draw different pictures (else this test would hold trivially).
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b) EXPECT_NE(first[a], first[b]) << a << " vs " << b;
}

}  // namespace
}  // namespace ewa::test

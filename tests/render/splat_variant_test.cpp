// Splat and slab pass program variants: each frame compiles in only the paths its settings use
// (MIP, post, halves, clipping; the slab pass's shading, pre-integration, field normals, order);
// switching between them must leave every picture as a fresh renderer draws it.
#include <cmath>
#include <set>

#include "render/slab_pass_programs.h"
#include "render/splat_programs.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SplatVariants : public RenderFixture {};

// Every combination of a variant's `switches` switches has its own key and #define lines, each
// switch's line saying its value.
template <class Variant, class Set>
void expectEveryCombinationDistinct(unsigned switches, Set set) {
  std::set<unsigned> keys;
  std::set<std::string> defines;
  const unsigned combinations = 1u << switches;
  for (unsigned bits = 0; bits < combinations; ++bits) {
    Variant v;
    set(v, bits);
    keys.insert(v.key());
    defines.insert(v.defines());
    for (const auto& [name, on] : v.flags())
      EXPECT_NE(v.defines().find(std::string("#define ") + name + (on ? " 1\n" : " 0\n")),
                std::string::npos)
          << name;
  }
  EXPECT_EQ(keys.size(), combinations);
  EXPECT_EQ(defines.size(), combinations);
}

TEST(SplatVariant, EveryCombinationHasItsOwnKeyAndDefines) {
  expectEveryCombinationDistinct<SplatVariant>(6, [](SplatVariant& v, unsigned bits) {
    v.mip = bits & 1;
    v.post = bits & 2;
    v.halves = bits & 4;
    v.clip = bits & 8;
    v.texelBuffers = bits & 16;
    v.erfSeries = bits & 32;
  });
}

TEST(SlabPassVariant, EveryCombinationHasItsOwnKeyAndDefines) {
  expectEveryCombinationDistinct<SlabPassVariant>(6, [](SlabPassVariant& v, unsigned bits) {
    v.post = bits & 1;
    v.preintegrated = bits & 2;
    v.shading = bits & 4;
    v.fieldNormals = bits & 8;
    v.neighbourInFront = bits & 16;
    v.scaled = bits & 32;
  });
}

constexpr int kVariantSettings = 9;

RenderSettings variantSettings(int which) {
  RenderSettings s = paperSettings();
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
    case 5:  // the slab pass's variants: shaded post with field normals, then voxel normals
      s.classification.mode = ClassificationMode::Post;
      s.lighting.enabled = true;
      break;
    case 6:
      s.classification.mode = ClassificationMode::Post;
      s.lighting.enabled = true;
      s.postNormals = PostNormals::Voxel;
      break;
    case 7:  // pre-integrated back to front: the neighbour lies behind
      s.classification.mode = ClassificationMode::Post;
      s.order = CompositeOrder::BackToFront;
      break;
    case 8:
      s.lighting.enabled = true;
      break;
    default:
      break;
  }
  return s;
}

// One renderer drawing pre, MIP, post with and without halves, clipped, shaded post (field and
// voxel normals), post back to front and shaded pre, each twice, gives what a renderer that
// never drew anything else gives, bit for bit.
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
  const int sequence[] = {0, 1, 2, 5, 3, 6, 4, 7, 0, 8, 4, 2, 6, 1, 7, 3, 5, 8};
  std::vector<std::vector<uint8_t>> first(kVariantSettings);
  // Pictures compared to the bit need the CPU partition: the GPU's scatter orders a slab's
  // entries differently from frame to frame, and the sums' rounding with them (voxel normals,
  // summed in a half-float image, showed it: a level in some 40 channels, under load).
  renderer()->setPartition(PartitionMode::Cpu);
  for (int which : sequence) {
    renderer()->render(cam, variantSettings(which), size, size);
    const Image8 img = renderer()->readImage();
    if (first[which].empty()) {
      first[which] = img.pixels;
      const gl::ShaderLibrary shaders;
      SplatRenderer fresh(shaders);
      fresh.setPartition(PartitionMode::Cpu);
      fresh.setVolume(vol);
      fresh.setTransferFunction(tf);
      fresh.render(cam, variantSettings(which), size, size);
      EXPECT_EQ(fresh.readImage().pixels, img.pixels) << "variant " << which;
    } else {
      EXPECT_EQ(first[which], img.pixels) << "variant " << which << " drawn again";
    }
  }
  // The variants draw different pictures (else this test would hold trivially).
  for (int a = 0; a < kVariantSettings; ++a)
    for (int b = a + 1; b < kVariantSettings; ++b)
      EXPECT_NE(first[a], first[b]) << a << " vs " << b;
}

// prepare() compiles what a frame under its settings needs: the frame after it compiles nothing
// more, and draws what a renderer that was not prepared draws.
TEST_F(SplatVariants, PreparedRendererCompilesNothingInItsFirstFrame) {
  const Volume vol = floatVolume(16, [](int i, int j, int k) {
    return float(std::max(0.0, 7.0 - glm::length(glm::dvec3(i, j, k) - glm::dvec3(7.5))));
  });
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {3.0, 0.4}, {7.0, 0.9}};
  tf.color = {{0.0, glm::dvec3(0.3, 0.5, 1.0)}, {7.0, glm::dvec3(1.0, 0.7, 0.2)}};
  Camera cam;
  cam.focalPoint = glm::dvec3(7.5);
  cam.position = cam.focalPoint + glm::dvec3(6.0, -8.0, 16.0);  // near: coarse slabs too
  for (int which : {0, 2, 5, 7}) {
    const RenderSettings settings = variantSettings(which);
    const gl::ShaderLibrary shaders;
    SplatRenderer prepared(shaders), plain(shaders);
    for (SplatRenderer* r : {&prepared, &plain}) {
      r->setVolume(vol);
      r->setTransferFunction(tf);
      r->setPartition(PartitionMode::Cpu);
    }
    prepared.prepare(settings, 96, 96);
    const size_t compiled = prepared.programsCompiled();
    prepared.render(cam, settings, 96, 96);
    EXPECT_EQ(prepared.programsCompiled(), compiled) << "variant " << which;
    plain.render(cam, settings, 96, 96);
    EXPECT_EQ(prepared.readImage().pixels, plain.readImage().pixels) << "variant " << which;
  }
}

// Splat lists larger than a storage block (llvmpipe: 128 MiB, 16.8 M splats) are read from
// texel buffers and the order list is bound in windows: with a 2 KiB block a small volume takes
// those paths, and every picture (composite, shaded, X-ray, MIP, post with halves, the quad
// path) is the same bit for bit.
TEST_F(SplatVariants, HugeSplatListPathsDrawTheSamePictures) {
  const Volume vol = floatVolume(20, [](int i, int j, int k) {
    return float(std::max(0.0, 9.0 - glm::length(glm::dvec3(i, j, k) - glm::dvec3(9.5))));
  });
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {3.0, 0.4}, {9.0, 1.0}};
  tf.color = {{0.0, glm::dvec3(0.3, 0.5, 1.0)}, {9.0, glm::dvec3(1.0, 0.7, 0.2)}};
  tf.opacityUnitDistance = 2.0;
  Camera cam;
  cam.focalPoint = glm::dvec3(9.5);
  cam.position = cam.focalPoint + glm::dvec3(-15.0, 20.0, 45.0);
  std::vector<RenderSettings> settings(6, rasterSettings());
  settings[1].lighting.enabled = true;
  settings[2].mode = RenderMode::XRay;
  settings[3].mode = RenderMode::Mip;
  settings[4].classification.mode = ClassificationMode::Post;
  settings[5].lighting.enabled = true;  // drawn through the quad path below
  const gl::ShaderLibrary shaders;
  SplatRenderer plain(shaders), windowed(shaders);
  windowed.setStorageBlockLimit(2048);
  for (SplatRenderer* r : {&plain, &windowed}) {
    r->setVolume(vol);
    r->setTransferFunction(tf);
    r->setPartition(PartitionMode::Cpu);
  }
  for (size_t i = 0; i < settings.size(); ++i) {
    const float points = i == 5 ? 2.0f : 1e9f;
    plain.setPointSizeLimit(points);
    windowed.setPointSizeLimit(points);
    plain.render(cam, settings[i], 48, 40);
    windowed.render(cam, settings[i], 48, 40);
    ASSERT_FALSE(plain.texelBuffers());
    ASSERT_TRUE(windowed.texelBuffers()) << windowed.splats().size() << " splats";
    // Whole slabs span several windows of the order list (2 KiB: under 512 entries).
    EXPECT_GT(windowed.stats().slabEntries / std::max<size_t>(1, windowed.stats().slabsDrawn),
              i == 2 || i == 3 ? 2000u : 600u)
        << i;
    EXPECT_EQ(plain.stats().slabEntries, windowed.stats().slabEntries) << i;
    EXPECT_EQ(plain.readImage().pixels, windowed.readImage().pixels) << "settings " << i;
  }
}

}  // namespace
}  // namespace ewa::test

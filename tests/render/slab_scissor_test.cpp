// Slab rectangles: each slab's clear, splats, composite and mark passes cut to the pixels its
// kernels can reach (core/slab_rect.h) give the same picture, to the bit, as whole-image passes.
#include <cmath>

#include "render_fixture.h"

namespace ewa::test {
namespace {

class SlabScissor : public RenderFixture {};

// A ball of varying density, off the view's centre, small in the image: the slabs near its
// front and back reach few pixels.
Volume ball() {
  const int n = 20;
  std::vector<uint8_t> bytes(size_t(n) * n * n, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double r =
            std::sqrt((i - 9.5) * (i - 9.5) + (j - 9.5) * (j - 9.5) + (k - 9.5) * (k - 9.5));
        if (r < 9.0) bytes[i + n * (j + size_t(n) * k)] = uint8_t(60 + 20 * (int(i + 2 * k) % 9));
      }
  return Volume({n, n, n}, glm::dvec3(1.0, 1.0, 1.5), glm::dvec3(0.0), ScalarType::UInt8,
                std::move(bytes));
}

TransferFunction ballTf() {
  TransferFunction tf;
  tf.opacity = {{40.0, 0.0}, {60.0, 0.15}, {220.0, 0.6}};
  tf.color = {{0.0, {0.9, 0.3, 0.2}}, {140.0, {0.2, 0.8, 0.4}}, {255.0, {0.3, 0.4, 1.0}}};
  return tf;
}

TEST_F(SlabScissor, SamePictureAsWholeImagePasses) {
  // The CPU partition: the GPU's scatters each slab's entries in an order that varies from
  // frame to frame (atomics), and the sums' rounding with it (a level in a few pixels of the
  // post-classified picture); this test compares pictures to the bit.
  renderer()->setPartition(PartitionMode::Cpu);
  const Volume vol = ball();
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(ballTf());
  Camera cam;
  cam.focalPoint = {4.0, 14.0, 10.0};  // the ball sits off centre
  cam.position = cam.focalPoint + glm::dvec3(25.0, 20.0, 70.0);
  RenderSettings base = rasterSettings();  // slab passes
  base.terminationOpacity = 0.9;           // marks and termination happen in the picture
  struct Case {
    const char* name;
    RenderSettings settings;
    bool orthographic;
    double stepMs;  // 0: render() whole; else budgeted steps of this many ms
  };
  std::vector<Case> cases;
  cases.push_back({"perspective", base, false, 0.0});
  cases.push_back({"orthographic", base, true, 0.0});
  cases.push_back({"budgeted steps", base, false, 0.5});
  // Every slab's pass in bands of rows over several steps, the marks after the last band.
  cases.push_back({"tiny steps", base, false, 1e-6});
  RenderSettings thin = base;
  thin.slabThickness = 0.5;
  cases.push_back({"thin slabs", thin, false, 0.0});
  RenderSettings backToFront = base;
  backToFront.order = CompositeOrder::BackToFront;
  cases.push_back({"back to front", backToFront, false, 0.0});
  RenderSettings post = base;
  post.classification.mode = ClassificationMode::Post;
  post.lighting.enabled = true;
  cases.push_back({"post-classified, shaded", post, false, 0.0});
  RenderSettings postFlat = base;
  postFlat.classification.mode = ClassificationMode::Post;
  cases.push_back({"post-classified, flat", postFlat, false, 0.0});
  RenderSettings shaded = base;
  shaded.lighting.enabled = true;
  cases.push_back({"pre-classified, shaded", shaded, false, 0.0});
  RenderSettings swan = base;
  swan.filter = FilterMode::Swan;
  cases.push_back({"swan", swan, false, 0.0});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Camera view = cam;
    view.orthographic = c.orthographic;
    Image8 images[2];
    for (int on = 0; on < 2; ++on) {
      renderer()->setSlabScissor(on == 1);
      if (c.stepMs > 0.0) {
        renderer()->beginFrame(view, c.settings, 96, 80);
        while (!renderer()->stepFrame(c.stepMs)) {
        }
      } else {
        renderer()->render(view, c.settings, 96, 80);
      }
      images[on] = renderer()->readImage();
    }
    renderer()->setSlabScissor(true);
    ASSERT_EQ(images[0].pixels.size(), images[1].pixels.size());
    size_t differing = 0, lit = 0;
    for (size_t p = 0; p < images[0].pixels.size(); ++p) {
      differing += images[0].pixels[p] != images[1].pixels[p];
      lit += images[0].pixels[p] > 8;
    }
    EXPECT_GT(lit, 300u) << "the ball should be in the picture";
    EXPECT_EQ(differing, 0u) << "slab rectangles changed the picture";
  }
}

}  // namespace
}  // namespace ewa::test

// Pre-integration between post-classified slabs: thin transfer-function peaks (iso-surfaces)
// come out as closed surfaces, where classifying each slab's mean value alone leaves holes.
#include <cmath>

#include "core/synthetic_volume.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class SlabPreintegration : public RenderFixture {};

// Opaque white in a band `width` wide about `value`, transparent elsewhere.
TransferFunction thinPeak(double value, double width) {
  TransferFunction tf;
  tf.opacity = {{value - width, 0.0},
                {value - 0.3 * width, 1.0},
                {value + 0.3 * width, 1.0},
                {value + width, 0.0}};
  tf.color = {{value, glm::dvec3(1.0)}};
  tf.opacityUnitDistance = 0.1;  // opaque where a ray crosses the band
  return tf;
}

struct Coverage {
  double covered;  // share of the disk's pixels brighter than 0.9 (white: opacity)
  double spread;   // standard deviation of their brightness (0..1)
};

// Brightness statistics over the disk of `radius` pixels about the image's centre.
Coverage diskCoverage(const Image8& img, double radius) {
  double n = 0, covered = 0, sum = 0, sum2 = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (std::hypot(x + 0.5 - img.width / 2.0, y + 0.5 - img.height / 2.0) > radius) continue;
      const double a = img.pixels[(size_t(y) * img.width + x) * 3] / 255.0;
      n += 1;
      covered += a > 0.9;
      sum += a;
      sum2 += a * a;
    }
  return {covered / n, std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)))};
}

// Looks at the centre of `vol` from `direction` (slightly off an axis), perspective.
Camera lookAtCentre(const Volume& vol, const glm::dvec3& direction, double distance) {
  Camera cam;
  cam.focalPoint = 0.5 * (vol.boundsMin() + vol.boundsMax());
  cam.position = cam.focalPoint + distance * glm::normalize(direction);
  cam.viewUp = {0.0, 1.0, 0.0};
  return cam;
}

RenderSettings postSettings(bool preintegration, CompositeOrder order) {
  RenderSettings s;
  s.classification.mode = ClassificationMode::Post;
  s.slabPreintegration = preintegration;
  s.order = order;
  return s;
}

// A sphere's distance field and a thin shell at radius 12 (the shear-warp renderer's test):
// every ray through the inner disk crosses the shell twice.
TEST_F(SlabPreintegration, ThinShellIsClosedOnlyWithPreintegration) {
  const Volume vol = floatVolume(40, [](int i, int j, int k) {
    return float(glm::length(glm::dvec3(i, j, k) - glm::dvec3(19.5)));
  });
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(thinPeak(12.0, 0.3));
  const Camera cam = lookAtCentre(vol, {0.15, 0.1, 1.0}, 90.0);
  const int size = 96;
  // The shell's outline: radius 12 at distance 90 with a 30 degree view.
  const double radius = 12.0 / (90.0 * std::tan(M_PI / 12.0)) * size / 2.0;
  for (CompositeOrder order : {CompositeOrder::FrontToBack, CompositeOrder::BackToFront}) {
    renderer()->render(cam, postSettings(true, order), size, size);
    const Coverage pre = diskCoverage(renderer()->readImage(), 0.75 * radius);
    renderer()->render(cam, postSettings(false, order), size, size);
    const Coverage mean = diskCoverage(renderer()->readImage(), 0.75 * radius);
    std::printf(
        "thin shell, %s: pre-integrated covered %.3f spread %.3f; slab means covered "
        "%.3f spread %.3f\n",
        compositeOrderName(order), pre.covered, pre.spread, mean.covered, mean.spread);
    EXPECT_GT(pre.covered, 0.99) << compositeOrderName(order);
    EXPECT_LT(pre.spread, 0.03) << compositeOrderName(order);
    EXPECT_LT(mean.covered, 0.8) << compositeOrderName(order);
    EXPECT_GT(mean.spread, 0.1) << compositeOrderName(order);
  }
}

// Marschner-Lobb's 0.5 iso-surface as a thin peak, seen from above: every ray entering
// through the top face (values below 0.3) reaches values above 0.8 at the bottom, so it crosses
// the surface.
TEST_F(SlabPreintegration, MarschnerLobbIsoSurfaceIsClosedOnlyWithPreintegration) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  renderer()->setVolume(ml.volume);
  renderer()->setTransferFunction(thinPeak(0.5, 0.02));
  const Camera cam = lookAtCentre(ml.volume, {0.05, -0.08, 1.0}, 120.0);
  const int size = 96;
  // The top face (z = 40) is 100 units away: its half width of 20 units in pixels.
  const double halfWidth = 20.0 / (100.0 * std::tan(M_PI / 12.0)) * size / 2.0;
  renderer()->render(cam, postSettings(true, CompositeOrder::FrontToBack), size, size);
  const Coverage pre = diskCoverage(renderer()->readImage(), 0.6 * halfWidth);
  renderer()->render(cam, postSettings(false, CompositeOrder::FrontToBack), size, size);
  const Coverage mean = diskCoverage(renderer()->readImage(), 0.6 * halfWidth);
  std::printf(
      "Marschner-Lobb 0.5: pre-integrated covered %.3f spread %.3f; slab means covered "
      "%.3f spread %.3f\n",
      pre.covered, pre.spread, mean.covered, mean.spread);
  EXPECT_GT(pre.covered, 0.99);
  EXPECT_LT(mean.covered, 0.8);
}

}  // namespace
}  // namespace ewa::test

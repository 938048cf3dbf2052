// Live transfer-function editing on the GPU: a new table shows without rebuilding the splats,
// and a set built on the worker thread draws the same picture as a full rebuild.
#include "core/async_splat_builder.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class LiveTransfer : public RenderFixture {};

// Values 1 in the left half of a 12^3 cube, 2 in the right half.
Volume twoHalves() {
  std::vector<uint8_t> bytes(12 * 12 * 12);
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) bytes[size_t(i + 12 * (j + 12 * k))] = i < 6 ? 1 : 2;
  return Volume({12, 12, 12}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
}

// Opacity `left` at value 1 and `right` at value 2; red at 1, green at 2.
TransferFunction halves(double left, double right) {
  TransferFunction tf;
  // Flat around each value, so a transparent half stays out of the splat set.
  tf.opacity = {{1.0, left}, {1.4, left}, {1.6, right}, {2.0, right}};
  tf.color = {{1.4, {1.0, 0.0, 0.0}}, {1.6, {0.0, 1.0, 0.0}}};
  return tf;
}

// Mean of channel c over the left or right third of the image.
double sideMean(const Image8& img, bool left, int c) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = left ? 0 : 2 * img.width / 3; x < (left ? img.width / 3 : img.width); ++x, ++n)
      sum += img.pixels[size_t(y * img.width + x) * 3 + c];
  return sum / n;
}

TEST_F(LiveTransfer, NewTableShowsAtOnceAndWorkerSetMatchesFullRebuild) {
  const Volume vol = twoHalves();
  Camera cam;
  cam.frame(vol.boundsMin(), vol.boundsMax(), {0, 0, 1}, {0, 1, 0}, 1.0);
  const RenderSettings settings = paperSettings();
  const int size = 48;
  // Pictures compared to the bit: the CPU partition, whose order of a slab's entries (and so
  // the sums' rounding, seen in half-float slab images) does not vary between frames.
  renderer()->setPartition(PartitionMode::Cpu);
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(halves(0.0, 0.3));  // left half transparent: not uploaded
  renderer()->render(cam, settings, size, size);
  const size_t rightOnly = renderer()->splats().size();
  EXPECT_EQ(rightOnly, size_t(6 * 12 * 12));
  const Image8 before = renderer()->readImage();
  EXPECT_LT(sideMean(before, true, 0), 1.0);
  EXPECT_GT(sideMean(before, false, 1), 40.0);

  // Raise the right half's opacity and turn its colour blue: the next frame shows it with the
  // same splats (no rebuild).
  TransferFunction edited = halves(0.0, 0.6);
  edited.color[1].rgb = {0.0, 0.0, 1.0};
  renderer()->updateTransferTexture(edited);
  renderer()->render(cam, settings, size, size);
  EXPECT_EQ(renderer()->splats().size(), rightOnly);
  const Image8 recoloured = renderer()->readImage();
  EXPECT_LT(sideMean(recoloured, false, 1), 1.0);
  EXPECT_GT(sideMean(recoloured, false, 2), sideMean(before, false, 1));

  // Make the left half visible: it appears once the worker's set is swapped in, and that
  // picture equals a full rebuild's.
  const TransferFunction both = halves(0.3, 0.3);
  renderer()->updateTransferTexture(both);
  renderer()->render(cam, settings, size, size);
  EXPECT_LT(sideMean(renderer()->readImage(), true, 0), 1.0);  // old set: nothing there yet
  AsyncSplatBuilder builder;
  builder.request(vol, both);
  std::optional<BuiltSplats> built = builder.finish();
  ASSERT_TRUE(built.has_value());
  renderer()->setSplats(std::move(built->splats), built->classification);
  renderer()->render(cam, settings, size, size);
  EXPECT_EQ(renderer()->splats().size(), size_t(12 * 12 * 12));
  const Image8 swapped = renderer()->readImage();
  EXPECT_GT(sideMean(swapped, true, 0), 40.0);
  renderer()->setTransferFunction(both);
  renderer()->render(cam, settings, size, size);
  EXPECT_EQ(renderer()->readImage().pixels, swapped.pixels);
}

}  // namespace
}  // namespace ewa::test

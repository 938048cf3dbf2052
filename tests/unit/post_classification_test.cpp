// The voxels post-classified splatting keeps: visible ones, transfer-function crossings between
// neighbours, and a margin as wide as a kernel reaches.
#include "core/post_classification.h"

#include <gtest/gtest.h>

#include "core/splat_attributes.h"

namespace ewa {
namespace {

Volume line(const std::vector<uint8_t>& values) {
  return Volume({int64_t(values.size()), 1, 1}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
                values);
}

TEST(PostClassification, MarginFollowsTheKernelsReach) {
  EXPECT_EQ(postClassificationMargin(4.0, 1.0), 2);
  EXPECT_EQ(postClassificationMargin(4.0, 0.85), 2);
  EXPECT_EQ(postClassificationMargin(4.0, 0.7), 1);
  EXPECT_EQ(postClassificationMargin(4.0, 0.5), 1);
  EXPECT_EQ(postClassificationMargin(9.0, 1.5), 5);
  EXPECT_EQ(postClassificationMargin(4.0, 0.1), 1);  // never none: neighbours always matter
}

TEST(PostClassification, MaskDilatesVisibleVoxelsByTheMargin) {
  const Volume v = line({0, 0, 0, 0, 0, 255, 0, 0, 0, 0, 0});
  const auto visible = [](double x) { return x > 200.0; };
  const std::vector<uint8_t> expected = {0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0};
  EXPECT_EQ(postClassificationMask(v, visible, 2), expected);
  const std::vector<uint8_t> none(11, 0);
  EXPECT_EQ(postClassificationMask(
                v, [](double) { return false; }, 2),
            none);
}

TEST(PostClassification, MaskFindsPeaksBetweenNeighbouringValues) {
  // Neither 20 nor 240 is visible, but the value passes 128 between them.
  const Volume v = line({20, 20, 20, 240, 240, 240, 240});
  const auto peak = [](double x) { return x > 120.0 && x < 136.0; };
  const std::vector<uint8_t> expected = {0, 1, 1, 1, 1, 0, 0};
  EXPECT_EQ(postClassificationMask(v, peak, 1), expected);
}

TEST(PostClassification, ClassifiedSplatsKeepTheMarginAndNoSurfaces) {
  std::vector<uint8_t> bytes(9 * 9 * 9, 0);
  bytes[4 + 9 * (4 + 9 * 4)] = 255;
  const Volume v({9, 9, 9}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8, bytes);
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {100.0, 0.0}, {200.0, 1.0}, {255.0, 1.0}};
  Classification c;
  c.surface = SurfaceCriterion::Value;
  c.threshold = 128.0;
  EXPECT_EQ(classifySplats(v, tf, c).splats.size(), 1u);
  c.mode = ClassificationMode::Post;
  c.postMargin = 1;
  const ClassifiedSplats post = classifySplats(v, tf, c);
  EXPECT_EQ(post.splats.size(), 27u);
  EXPECT_EQ(post.surfaceCount, 0u);
  std::string name = classificationModeName(ClassificationMode::Post);
  ClassificationMode parsed = ClassificationMode::Pre;
  EXPECT_TRUE(parseClassificationMode(name, &parsed));
  EXPECT_EQ(parsed, ClassificationMode::Post);
  EXPECT_FALSE(parseClassificationMode("mid", &parsed));
}

}  // namespace
}  // namespace ewa

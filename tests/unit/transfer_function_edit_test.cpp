// Unit tests of transfer-function editing (add, move, remove), presets and the editor's canvas.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/transfer_function.h"
#include "core/transfer_function_presets.h"
#include "ui/tf_canvas.h"

namespace ewa {
namespace {

TransferFunction threePoints() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {50.0, 0.5}, {100.0, 1.0}};
  tf.color = {{0.0, {1.0, 0.0, 0.0}}, {100.0, {0.0, 0.0, 1.0}}};
  return tf;
}

TEST(TransferFunctionEdit, AddInsertsInOrderAndChangesTheCurve) {
  TransferFunction tf = threePoints();
  EXPECT_DOUBLE_EQ(tf.alphaAt(25.0), 0.25);
  EXPECT_EQ(tf.addOpacityPoint(25.0, 0.9), 1u);
  EXPECT_DOUBLE_EQ(tf.alphaAt(25.0), 0.9);
  EXPECT_DOUBLE_EQ(tf.alphaAt(37.5), 0.7);  // halfway between 0.9 and 0.5
  EXPECT_EQ(tf.addOpacityPoint(200.0, 2.0), 4u);
  EXPECT_DOUBLE_EQ(tf.opacity[4].alpha, 1.0);  // clamped
  // A point at an existing value goes after it: the step rises at that value.
  EXPECT_EQ(tf.addOpacityPoint(50.0, 0.1), 3u);
  EXPECT_DOUBLE_EQ(tf.alphaAt(50.0), 0.1);
  EXPECT_NO_THROW(tf.validate());
  EXPECT_THROW(tf.addOpacityPoint(std::nan(""), 0.5), std::invalid_argument);
  EXPECT_EQ(tf.opacity.size(), 6u);

  EXPECT_EQ(tf.addColorPoint(50.0, {0.0, 2.0, -1.0}), 1u);
  EXPECT_EQ(tf.color[1].rgb, glm::dvec3(0.0, 1.0, 0.0));
  EXPECT_EQ(tf.colorAt(75.0), glm::dvec3(0.0, 0.5, 0.5));
  EXPECT_NO_THROW(tf.validate());
}

TEST(TransferFunctionEdit, MoveStaysBetweenNeighboursAndInRange) {
  TransferFunction tf = threePoints();
  tf.moveOpacityPoint(1, 70.0, 0.8);
  EXPECT_EQ(tf.opacity[1], (OpacityPoint{70.0, 0.8}));
  EXPECT_DOUBLE_EQ(tf.alphaAt(35.0), 0.4);
  tf.moveOpacityPoint(1, 500.0, 5.0);  // cannot pass the last point or exceed 1
  EXPECT_EQ(tf.opacity[1], (OpacityPoint{100.0, 1.0}));
  tf.moveOpacityPoint(1, -500.0, -1.0);
  EXPECT_EQ(tf.opacity[1], (OpacityPoint{0.0, 0.0}));
  tf.moveOpacityPoint(1, std::nan(""), std::numeric_limits<double>::infinity());
  EXPECT_EQ(tf.opacity[1], (OpacityPoint{0.0, 0.0}));  // non-finite keeps the old coordinates
  tf.moveOpacityPoint(0, -10.0, 0.3);                  // the first point may go below the others
  EXPECT_EQ(tf.opacity[0], (OpacityPoint{-10.0, 0.3}));
  EXPECT_NO_THROW(tf.validate());
  EXPECT_THROW(tf.moveOpacityPoint(3, 1.0, 1.0), std::out_of_range);

  tf.moveColorPoint(0, 60.0);
  EXPECT_DOUBLE_EQ(tf.color[0].value, 60.0);
  tf.moveColorPoint(0, 160.0);
  EXPECT_DOUBLE_EQ(tf.color[0].value, 100.0);
  tf.setPointColor(1, {0.5, 1.5, 0.25});
  EXPECT_EQ(tf.color[1].rgb, glm::dvec3(0.5, 1.0, 0.25));
  EXPECT_THROW(tf.setPointColor(1, {std::nan(""), 0, 0}), std::invalid_argument);
  EXPECT_THROW(tf.moveColorPoint(2, 1.0), std::out_of_range);
  EXPECT_NO_THROW(tf.validate());
}

TEST(TransferFunctionEdit, RemoveDropsThePointAndReinterpolates) {
  TransferFunction tf = threePoints();
  tf.removeOpacityPoint(1);
  ASSERT_EQ(tf.opacity.size(), 2u);
  EXPECT_DOUBLE_EQ(tf.alphaAt(50.0), 0.5);  // now the straight line from 0 to 1
  EXPECT_DOUBLE_EQ(tf.alphaAt(25.0), 0.25);
  tf.removeOpacityPoint(1);
  tf.removeOpacityPoint(0);
  EXPECT_TRUE(tf.allTransparent(-1e9, 1e9));
  EXPECT_THROW(tf.removeOpacityPoint(0), std::out_of_range);
  tf.removeColorPoint(0);
  EXPECT_EQ(tf.colorAt(0.0), glm::dvec3(0.0, 0.0, 1.0));
  EXPECT_THROW(tf.removeColorPoint(1), std::out_of_range);
}

TEST(TransferFunctionPresets, KeysNameThePresetsOnTheCommandLine) {
  std::vector<std::string> keys;
  for (const auto& info : transferFunctionPresets()) keys.push_back(info.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"ct-bone", "ct-soft-tissue", "mr", "grayscale-ramp",
                                            "viridis", "inferno", "cool-to-warm", "rainbow"}));
  const TransferFunction current = threePoints();
  for (const auto& info : transferFunctionPresets())
    EXPECT_EQ(applyTransferFunctionPreset(current, info.key, 0.0, 255.0),
              applyTransferFunctionPreset(current, info.name, 0.0, 255.0))
        << info.key;
  EXPECT_THROW(applyTransferFunctionPreset(current, "CT-bone", 0.0, 255.0), std::invalid_argument);
}

TEST(TransferFunctionPresets, EveryPresetIsValidAndScaledToTheRange) {
  TransferFunction current = threePoints();
  current.opacityUnitDistance = 0.5;
  for (const double lo : {0.0, -1024.0, 1000.0}) {
    const double hi = lo + 3000.0;
    for (const auto& info : transferFunctionPresets()) {
      SCOPED_TRACE(info.name + " lo " + std::to_string(lo));
      const TransferFunction tf = applyTransferFunctionPreset(current, info.name, lo, hi);
      EXPECT_NO_THROW(tf.validate());
      EXPECT_EQ(tf.opacityUnitDistance, 0.5);
      ASSERT_FALSE(tf.color.empty());
      EXPECT_GE(tf.color.front().value, lo);
      EXPECT_LE(tf.color.back().value, hi);
      if (info.colorOnly) {
        EXPECT_EQ(tf.opacity, current.opacity);  // a colour map keeps the opacity
      } else {
        EXPECT_GE(tf.opacity.front().value, lo);
        EXPECT_LE(tf.opacity.back().value, hi);
        EXPECT_FALSE(tf.allTransparent(lo, hi));
      }
    }
  }
  EXPECT_THROW(applyTransferFunctionPreset(current, "no such preset", 0, 1), std::invalid_argument);
  EXPECT_THROW(applyTransferFunctionPreset(current, "MR", 1, 0), std::invalid_argument);
}

TEST(TransferFunctionPresets, BoneIsOpaqueAndSoftTissueFaintInHounsfieldUnits) {
  const TransferFunction bone = applyTransferFunctionPreset({}, "CT bone", -1024, 3071);
  EXPECT_EQ(bone.alphaAt(-1000.0), 0.0);  // air
  EXPECT_EQ(bone.alphaAt(40.0), 0.0);     // soft tissue hidden
  EXPECT_GT(bone.alphaAt(1200.0), 0.5);   // cortical bone
  const TransferFunction soft = applyTransferFunctionPreset({}, "CT soft tissue", -1024, 3071);
  EXPECT_EQ(soft.alphaAt(-1000.0), 0.0);
  EXPECT_GT(soft.alphaAt(40.0), 0.0);
  EXPECT_LT(soft.alphaAt(40.0), 0.1);
  EXPECT_GT(soft.alphaAt(1200.0), soft.alphaAt(40.0));
  // Not HU (e.g. uint8 CT): [-1000, 2000] HU stretched over the range, 40 HU at 0.347.
  const TransferFunction bone8 = applyTransferFunctionPreset({}, "CT bone", 0, 255);
  EXPECT_EQ(bone8.alphaAt(255.0 * 1040.0 / 3000.0), 0.0);
  EXPECT_GT(bone8.alphaAt(255.0 * 2200.0 / 3000.0), 0.5);
}

TEST(TransferFunctionPresets, GrayscaleRampAndViridisEnds) {
  const TransferFunction gray = applyTransferFunctionPreset({}, "Grayscale ramp", 10, 20);
  EXPECT_EQ(gray.alphaAt(10.0), 0.0);
  EXPECT_DOUBLE_EQ(gray.alphaAt(15.0), 0.2);
  EXPECT_EQ(gray.colorAt(15.0), glm::dvec3(0.5));
  const TransferFunction viridis = applyTransferFunctionPreset({}, "Viridis (colour map)", 0, 1);
  EXPECT_NEAR(viridis.colorAt(0.0).b, 0.329, 1e-3);  // dark purple to yellow
  EXPECT_NEAR(viridis.colorAt(1.0).r, 0.993, 1e-3);
}

TEST(TfCanvas, MapsBothWaysAndPicksTheNearestPoint) {
  TfCanvas c;
  c.x = 100;
  c.y = 50;
  c.width = 200;
  c.height = 100;
  c.lo = -10;
  c.hi = 10;
  EXPECT_FLOAT_EQ(c.toX(0.0), 200.0f);
  EXPECT_FLOAT_EQ(c.toY(0.25), 125.0f);
  EXPECT_DOUBLE_EQ(c.toValue(250.0f), 5.0);
  EXPECT_DOUBLE_EQ(c.toAlpha(75.0f), 0.75);
  EXPECT_DOUBLE_EQ(c.toValue(0.0f), -10.0);  // clamped to the plot
  EXPECT_DOUBLE_EQ(c.toAlpha(500.0f), 0.0);

  TransferFunction tf;
  tf.opacity = {{-10.0, 0.0}, {0.0, 0.5}, {1.0, 0.5}};
  tf.color = {{-10.0, {1, 1, 1}}, {10.0, {0, 0, 0}}};
  EXPECT_EQ(c.pickOpacity(tf, 200.0f, 100.0f, 7.0f), 1);
  EXPECT_EQ(c.pickOpacity(tf, 209.0f, 100.0f, 7.0f), 2);  // point 2 sits at x = 210
  EXPECT_EQ(c.pickOpacity(tf, 200.0f, 120.0f, 7.0f), -1);
  EXPECT_EQ(c.pickOpacity(tf, 102.0f, 148.0f, 7.0f), 0);
  EXPECT_EQ(c.pickColor(tf, 296.0f, 7.0f), 1);
  EXPECT_EQ(c.pickColor(tf, 200.0f, 7.0f), -1);
}

}  // namespace
}  // namespace ewa

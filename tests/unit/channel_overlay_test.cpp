// The additive overlay of channel pictures and the channels' colours.
#include "core/channel_overlay.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ewa {
namespace {

Image8 picture(std::vector<uint8_t> rgb) {  // 2 x 1 pixels, RGB
  Image8 i;
  i.width = 2;
  i.height = 1;
  i.channels = 3;
  i.pixels = std::move(rgb);
  return i;
}

TEST(ChannelOverlay, ColoursAddOverBlackAndClamp) {
  const Image8 out = overlayChannels(
      {picture({100, 0, 100, 200, 10, 0}), picture({0, 200, 0, 100, 20, 5})}, {}, glm::dvec3(0));
  EXPECT_EQ(out.pixels, (std::vector<uint8_t>{100, 200, 100, 255, 30, 5}));
}

TEST(ChannelOverlay, TheBackgroundShowsThroughWhatEveryChannelLeaves) {
  // Over white each channel shows its opacity: 1 - a = (W - C) / 255, the mean of the three.
  const Image8 black1 = picture({100, 0, 100, 0, 0, 0}),
               white1 = picture({228, 128, 228, 255, 255, 255});
  const Image8 black2 = picture({0, 200, 0, 0, 0, 0}),
               white2 = picture({55, 255, 55, 255, 255, 255});
  const Image8 out = overlayChannels({black1, black2}, {white1, white2}, glm::dvec3(1.0, 0.0, 0.5));
  const double through = (128.0 / 255.0) * (55.0 / 255.0);
  EXPECT_EQ(out.pixels[0], uint8_t(std::lround(100 + 255 * through)));
  EXPECT_EQ(out.pixels[1], 200);
  EXPECT_EQ(out.pixels[2], uint8_t(std::lround(100 + 127.5 * through)));
  // Where no channel draws anything, the background itself.
  EXPECT_EQ(out.pixels[3], 255);
  EXPECT_EQ(out.pixels[4], 0);
  EXPECT_EQ(out.pixels[5], 128);
}

TEST(ChannelOverlay, PicturesMustAgree) {
  Image8 small = picture({1, 2, 3, 4, 5, 6});
  Image8 wide = small;
  wide.width = 1;
  wide.pixels.resize(3);
  EXPECT_THROW(overlayChannels({small, wide}, {}, glm::dvec3(0)), std::invalid_argument);
  EXPECT_THROW(overlayChannels({}, {}, glm::dvec3(0)), std::invalid_argument);
  EXPECT_THROW(overlayChannels({small, small}, {small}, glm::dvec3(1)), std::invalid_argument);
}

TEST(ChannelOverlay, ColoursAndTransferFunctions) {
  EXPECT_EQ(channelColor(0, 2), glm::dvec3(1, 0, 1));  // magenta and green for two
  EXPECT_EQ(channelColor(1, 2), glm::dvec3(0, 1, 0));
  EXPECT_EQ(channelColor(0, 3), glm::dvec3(1, 0, 0));  // red, green, blue, grey, cyan, ...
  EXPECT_EQ(channelColor(1, 3), glm::dvec3(0, 1, 0));
  EXPECT_EQ(channelColor(2, 3), glm::dvec3(0, 0, 1));
  EXPECT_EQ(channelColor(3, 5), glm::dvec3(1, 1, 1));
  EXPECT_EQ(channelColor(4, 5), glm::dvec3(0, 1, 1));
  EXPECT_EQ(channelColor(7, 8), channelColor(0, 8));
  TransferFunction tf;
  tf.opacity = {{0, 0}, {10, 0.5}};
  tf.color = {{0, {0.2, 0.3, 0.4}}, {10, {1, 1, 1}}};
  const TransferFunction green = inChannelColor(tf, {0, 1, 0});
  EXPECT_EQ(green.opacity.size(), 2u);
  EXPECT_DOUBLE_EQ(green.alphaAt(5), tf.alphaAt(5));
  EXPECT_EQ(green.colorAt(3), glm::dvec3(0, 1, 0));
  EXPECT_EQ(green.colorAt(10), glm::dvec3(0, 1, 0));
  EXPECT_NO_THROW(green.validate());
}

}  // namespace
}  // namespace ewa

// EGL device choice without a GPU: the EWAVIEW_EGL_DEVICE parser and the device of each
// node-local rank among hardware and software devices.
#include "platform/egl_device_choice.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace ewa::platform {
namespace {

TEST(EglDeviceChoice, ParsesWholeNumbersOnly) {
  EXPECT_EQ(parseEglDeviceIndex("0", "X"), 0);
  EXPECT_EQ(parseEglDeviceIndex("7", "X"), 7);
  EXPECT_EQ(parseEglDeviceIndex("12", "X"), 12);
  for (const char* bad : {"", "-1", "+1", " 1", "1 ", "1x", "one", "1.0", "99999999"}) {
    try {
      parseEglDeviceIndex(bad, "EWAVIEW_EGL_DEVICE");
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("EWAVIEW_EGL_DEVICE=\"" + std::string(bad) + "\""), std::string::npos)
          << message;
      EXPECT_EQ(message.find('\n'), std::string::npos);
    }
  }
}

TEST(EglDeviceChoice, ReadsTheVariable) {
  ::unsetenv("EWAVIEW_EGL_DEVICE");
  EXPECT_FALSE(eglDeviceFromEnvironment().has_value());
  ::setenv("EWAVIEW_EGL_DEVICE", "", 1);
  EXPECT_FALSE(eglDeviceFromEnvironment().has_value());
  ::setenv("EWAVIEW_EGL_DEVICE", "3", 1);
  EXPECT_EQ(eglDeviceFromEnvironment(), 3);
  ::setenv("EWAVIEW_EGL_DEVICE", "gpu3", 1);
  EXPECT_THROW(eglDeviceFromEnvironment(), std::invalid_argument);
  ::unsetenv("EWAVIEW_EGL_DEVICE");
}

TEST(EglDeviceChoice, RanksGoRoundTheHardwareDevices) {
  // 4 GPUs: 8 ranks on the node, 2 on each.
  const std::vector<bool> four(4, false);
  const int expected[8] = {0, 1, 2, 3, 0, 1, 2, 3};
  for (int r = 0; r < 8; ++r) EXPECT_EQ(eglDeviceForLocalRank(r, four), expected[r]) << r;
  // Mesa's software device listed among them (here second) is skipped.
  const std::vector<bool> mixed = {false, true, false, false, false};
  const int skipping[5] = {0, 2, 3, 4, 0};
  for (int r = 0; r < 5; ++r) EXPECT_EQ(eglDeviceForLocalRank(r, mixed), skipping[r]) << r;
  // Software devices alone (llvmpipe): they are all there is.
  EXPECT_EQ(eglDeviceForLocalRank(3, {true}), 0);
  EXPECT_EQ(eglDeviceForLocalRank(3, {true, true}), 1);
  EXPECT_EQ(eglDeviceForLocalRank(0, {}), -1);
  EXPECT_EQ(eglDeviceForLocalRank(-1, four), 0);
}

TEST(EglDeviceChoice, LocalRankIsSetForTheProcess) {
  EXPECT_EQ(eglLocalRank(), -1);
  setEglLocalRank(5);
  EXPECT_EQ(eglLocalRank(), 5);
  setEglLocalRank(-3);
  EXPECT_EQ(eglLocalRank(), -1);
}

}  // namespace
}  // namespace ewa::platform

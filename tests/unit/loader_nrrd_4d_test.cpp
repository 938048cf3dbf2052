// 4D NRRD files: a time or list axis last (--frame), a colour axis first (--channel), and the
// headers that do not say which axis is not spatial.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::gzipBytes;
using testing::TempDir;

// Three volumes of 2 x 3 x 4 uint8, volume t holding 100 t + n at voxel n (x fastest).
std::string timeData(int frames = 3) {
  std::string bytes;
  for (int t = 0; t < frames; ++t)
    for (int n = 0; n < 24; ++n) bytes.push_back(char(100 * t + n));
  return bytes;
}

std::string head4d(const std::string& sizes, const std::string& fields) {
  return "NRRD0004\ntype: uint8\ndimension: 4\nsizes: " + sizes + "\n" + fields;
}

void expectVolume(const Volume& v, int first) {
  ASSERT_EQ(v.dims(), (std::array<int64_t, 3>{2, 3, 4}));
  for (int n = 0; n < 24; ++n) ASSERT_EQ(v.valueAt(n), first + n) << "voxel " << n;
}

const std::string kTimeFields =
    "space: left-posterior-superior\nspace directions: (1,0,0) (0,1,0) (0,0,2) none\n"
    "kinds: domain domain domain list\n";

TEST(Nrrd4d, TimeLastOpensOneFrameAtATime) {
  TempDir dir;
  const std::string path =
      dir.write("t.nrrd", head4d("2 3 4 3", kTimeFields + "encoding: raw\n\n") + timeData());
  const Volume first = loadVolume(path);
  expectVolume(first, 0);
  EXPECT_EQ(first.frame(), 0);
  EXPECT_EQ(first.frameCount(), 3);
  EXPECT_DOUBLE_EQ(first.spacing().z, 2.0);
  EXPECT_TRUE(first.patientFrame());
  const Volume last = loadVolume(path, {"", 2, 0, {}});
  expectVolume(last, 200);
  EXPECT_EQ(last.frame(), 2);
  ASSERT_FALSE(last.notes().empty());
  EXPECT_EQ(last.notes()[0],
            "4D NRRD of 3 frames (kind list); showing frame 2 (--frame N picks another)");
  expectLoadError(
      [&] {
        loadVolume(path, {"", 3, 0, {}});
      },
      path, "--frame 3 is out of range (the file has 3 frames)");
  // Gzip, detached: the whole file inflated, the frame cut out.
  dir.write("t.raw.gz", gzipBytes(timeData()));
  const std::string detached =
      dir.write("t.nhdr", head4d("2 3 4 3", kTimeFields + "encoding: gzip\ndata file: t.raw.gz\n"));
  expectVolume(loadVolume(detached, {"", 1, 0, {}}), 100);
  // One frame short: refused before reading, whichever frame is asked for.
  const std::string cut =
      dir.write("cut.nrrd", head4d("2 3 4 3", kTimeFields + "encoding: raw\n\n") + timeData(2));
  expectLoadError([&] { loadVolume(cut); }, cut, "truncated file or wrong sizes?");
}

TEST(Nrrd4d, ColourFirstOpensOneChannel) {
  TempDir dir;
  std::string bytes;  // RGB interleaved: channel c of voxel n is 10 c + n
  for (int n = 0; n < 24; ++n)
    for (int c = 0; c < 3; ++c) bytes.push_back(char(10 * c + n));
  const std::string path = dir.write(
      "rgb.nrrd",
      head4d("3 2 3 4", "kinds: RGB-color domain domain domain\nencoding: raw\n\n") + bytes);
  expectVolume(loadVolume(path), 0);
  const Volume green = loadVolume(path, {"", 0, 1, {}});
  expectVolume(green, 10);
  EXPECT_EQ(green.frameCount(), 1);  // channels are not frames
  EXPECT_EQ(green.channel(), 1);
  EXPECT_EQ(green.channelCount(), 3);
  EXPECT_EQ(green.notes().at(0),
            "4D NRRD of 3 channels (kind rgb-color); showing channel 1 (--channel N picks "
            "another)");
  expectLoadError([&] { loadVolume(path, {"", 0, 3, {}}); }, path, "--channel 3 is out of range");
}

TEST(Nrrd4d, HeadersThatDoNotNameOneOuterNonSpatialAxisFail) {
  TempDir dir;
  const std::string data = timeData();
  auto bad = [&](const std::string& name, const std::string& sizes, const std::string& fields,
                 const std::string& fragment) {
    expectVolumeLoadError(dir.write(name, head4d(sizes, fields + "encoding: raw\n\n") + data),
                          fragment);
  };
  bad("plain.nrrd", "2 3 4 3", "", "needs space directions or kinds saying which axis");
  bad("middle.nrrd", "2 3 4 3", "kinds: domain list domain domain\n",
      "must be the first or the last, not axis 1");
  bad("two.nrrd", "2 3 4 3", "space directions: (1,0,0) none (0,0,1) none\n",
      "exactly one axis that is not spatial");
  bad("kinds.nrrd", "2 3 4 3", "kinds: domain domain list\n", "kinds count does not match");
  bad("five.nrrd", "2 3 4 3", "dimension: 5\n", "unsupported dimension '5' (need 1 to 4)");
}

}  // namespace
}  // namespace ewa

// What real headers say and do not say: ITK's "??" orientation names no patient axes.
#include <gtest/gtest.h>

#include <string>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::TempDir;

TEST(RealHeaders, AnUnknownAnatomicalOrientationNamesNoPatientAxes) {
  TempDir dir;
  const std::string body =
      "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n";
  for (const std::string& unknown : {"??", "???", "RRA", "XYZ", ""}) {
    const std::string path =
        dir.write("u.mha", body + "AnatomicalOrientation = " + unknown +
                               "\nElementDataFile = LOCAL\n" + std::string(8, '\1'));
    EXPECT_FALSE(loadVolume(path).patientFrame()) << unknown;
  }
  for (const std::string& known : {"RAI", "LPS", "ail"}) {
    const std::string path =
        dir.write("k.mha", body + "AnatomicalOrientation = " + known +
                               "\nElementDataFile = LOCAL\n" + std::string(8, '\1'));
    EXPECT_TRUE(loadVolume(path).patientFrame()) << known;
  }
}

}  // namespace
}  // namespace ewa

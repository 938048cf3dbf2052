// Multi-dimensional TIFF: OME-TIFF's and ImageJ hyperstacks' channels and time points, in any
// plane order, with OME's physical pixel sizes.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "io/tiff_planes.h"
#include "io/volume_loader.h"
#include "loader_test_files.h"
#include "medical_test_files.h"
#include "tiff_plane_samples.h"

namespace ewa {
namespace {

using testing::expectLoadError;
using testing::expectPlanes;
using testing::planeRange;
using testing::TempDir;

std::string omeXml(const std::string& order) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\">"
         "<Image ID=\"Image:0\" Name=\"cells\"><Pixels DimensionOrder=\"XY" +
         order +
         "\" ID=\"Pixels:0\" PhysicalSizeX=\"0.3\" PhysicalSizeY=\"0.6\" PhysicalSizeZ=\"1.5\" "
         "SizeC=\"2\" SizeT=\"2\" SizeX=\"3\" SizeY=\"2\" SizeZ=\"3\" Type=\"uint16\">"
         "<Channel ID=\"Channel:0:0\" SamplesPerPixel=\"1\"/><TiffData/></Pixels></Image></OME>";
}

TEST(TiffPlanes, OmeTiffInEveryOrderOpensAChannelAndATimePoint) {
  TempDir dir;
  for (const std::string order : {"ZCT", "CZT", "ZTC", "TZC"}) {
    const std::string path = dir.path("cells_" + order + ".ome.tif");
    ASSERT_TRUE(
        testing::writeTiff(path, 3, 2, planeRange(order), SAMPLEFORMAT_UINT, 1, omeXml(order)));
    const Volume first = loadVolume(path);
    expectPlanes(first, 0, 0);
    // OME's physical sizes, not the resolution tags (which say 0.25 and 0.5 here).
    EXPECT_EQ(first.spacing(), glm::dvec3(0.3, 0.6, 1.5)) << order;
    EXPECT_EQ(first.unit(), "\xC2\xB5m");  // the schema's default
    EXPECT_EQ(first.frameCount(), 2);
    EXPECT_EQ(first.channelCount(), 2);
    for (int c = 0; c < 2; ++c)
      for (int t = 0; t < 2; ++t) expectPlanes(loadVolume(path, {"", t, c, {}}), c, t);
    expectLoadError([&] { loadVolume(path, {"", 0, 2, {}}); }, path, "--channel 2 is out of range");
    expectLoadError(
        [&] {
          loadVolume(path, {"", 2, 0, {}});
        },
        path, "--frame 2 is out of range (the file has 2 time points)");
  }
}

TEST(TiffPlanes, ImageJHyperstackWithTimePoints) {
  TempDir dir;
  const std::string path = dir.path("stack.tif");
  ASSERT_TRUE(testing::writeTiff(
      path, 3, 2, planeRange("CZT"), SAMPLEFORMAT_UINT, 1,
      "ImageJ=1.53t\nimages=12\nchannels=2\nslices=3\nframes=2\nhyperstack=true\nunit=micron\n"
      "spacing=2.5\n"));
  const Volume v = loadVolume(path, {"", 1, 1, {}});
  expectPlanes(v, 1, 1);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.25, 0.5, 2.5));  // ImageJ: the resolution tags
  std::string notes;
  for (const std::string& n : v.notes()) notes += n + "\n";
  EXPECT_NE(notes.find("2 time points; showing frame 1 (--frame N picks another)"),
            std::string::npos)
      << notes;
}

TEST(TiffPlanes, PlaneOrderOfDescriptions) {
  // Unreadable or unknown descriptions leave a plain stack: every page a slice.
  for (const std::string& text : {std::string("<OME><Pixels SizeZ=\"3"), std::string("scan 7"),
                                  std::string("<OME><Image/></OME>")}) {
    const TiffPlaneOrder o = tiffPlaneOrder("a.tif", text, 1);
    EXPECT_EQ(o.kind, "") << text;
    for (int p = 0; p < 5; ++p) EXPECT_EQ(tiffSliceOfPage(o, p, 0, 0), p);
  }
  // A prefixed OME document and its own unit; an RGB plane's samples are not pages.
  const TiffPlaneOrder rgb = tiffPlaneOrder(
      "b.tif",
      "<ome:OME><ome:Pixels DimensionOrder=\"XYZCT\" SizeZ=\"4\" SizeC=\"3\" SizeT=\"1\" "
      "PhysicalSizeZ=\"0.002\" PhysicalSizeZUnit=\"mm\" PhysicalSizeX=\"2\" "
      "PhysicalSizeXUnit=\"nm\"/></ome:OME>",
      3);
  EXPECT_EQ(rgb.kind, "OME");
  EXPECT_EQ(rgb.channels, 1);
  EXPECT_EQ(rgb.slices, 4);
  EXPECT_EQ(rgb.unit, "nm");
  EXPECT_DOUBLE_EQ(rgb.sizeX, 2.0);
  EXPECT_NEAR(rgb.sizeZ, 2000.0, 1e-9);  // 0.002 mm in nanometres
  EXPECT_EQ(tiffSliceOfPage(rgb, 3, 0, 0), 3);
  EXPECT_EQ(tiffSliceOfPage(rgb, 4, 0, 0), -1);  // past SizeZ
  EXPECT_FALSE(rgb.hasOrigin);
}

// The first plane's position is the origin, each coordinate from its own unit into the sizes'.
TEST(TiffPlanes, FirstPlanePositionIsTheOrigin) {
  auto order = [](const std::string& sizeUnit, const std::string& planes) {
    return tiffPlaneOrder("p.tif",
                          "<OME><Pixels DimensionOrder=\"XYCZT\" SizeZ=\"2\" SizeC=\"2\" "
                          "PhysicalSizeX=\"0.5\"" +
                              sizeUnit + "><TiffData/>" + planes + "</Pixels></OME>",
                          1);
  };
  // TheZ 1 and channel 1 come first in the file: the plane Z 0, C 0, T 0 is the one read.
  const TiffPlaneOrder um =
      order("",
            "<Plane TheZ=\"1\" TheC=\"0\" TheT=\"0\" PositionX=\"99\" PositionXUnit=\"\xC2\xB5m\"/>"
            "<Plane TheZ=\"0\" TheC=\"1\" TheT=\"0\" PositionX=\"98\" PositionXUnit=\"\xC2\xB5m\"/>"
            "<Plane TheZ=\"0\" TheC=\"0\" TheT=\"0\" PositionX=\"-1.5\" PositionXUnit=\"mm\" "
            "PositionY=\"20\" PositionYUnit=\"nm\" PositionZ=\"7\" PositionZUnit=\"\xC2\xB5m\"/>");
  ASSERT_TRUE(um.hasOrigin);
  EXPECT_NEAR(um.origin[0], -1500.0, 1e-9);  // in micrometres, the sizes' default
  EXPECT_NEAR(um.origin[1], 0.02, 1e-12);
  EXPECT_NEAR(um.origin[2], 7.0, 1e-12);
  // Positions without a unit are in OME's "reference frame": kept only when the sizes have none.
  const std::string bare = "<Plane TheZ=\"0\" TheC=\"0\" TheT=\"0\" PositionZ=\"4.5\"/>";
  EXPECT_FALSE(order("", bare).hasOrigin);
  const TiffPlaneOrder frame = order(" PhysicalSizeXUnit=\"reference frame\"", bare);
  ASSERT_TRUE(frame.hasOrigin);
  EXPECT_EQ(frame.origin, (std::array<double, 3>{0.0, 0.0, 4.5}));
  // A unit that is not a length, and numbers that are not finite, place nothing.
  EXPECT_FALSE(order("",
                     "<Plane TheZ=\"0\" TheC=\"0\" TheT=\"0\" PositionX=\"3\" "
                     "PositionXUnit=\"s\"/>")
                   .hasOrigin);
  const TiffPlaneOrder nan =
      order("",
            "<Plane TheZ=\"0\" TheC=\"0\" TheT=\"0\" PositionX=\"nan\" "
            "PositionXUnit=\"\xC2\xB5m\" PositionY=\"inf\" PositionYUnit=\"\xC2\xB5m\"/>");
  EXPECT_EQ(nan.origin, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

// A pixel size given for one axis only stands for both (square pixels), with a note; none at
// all is 1, with another.
TEST(TiffPlanes, OnePixelSizeStandsForBoth) {
  TempDir dir;
  const std::vector<std::vector<uint8_t>> pages(2, std::vector<uint8_t>(6, 7));
  const auto open = [&](const std::string& name, const std::string& sizes) {
    const std::string xml =
        "<OME><Image><Pixels DimensionOrder=\"XYZCT\" SizeX=\"3\" SizeY=\"2\" SizeZ=\"2\" " +
        sizes + " Type=\"uint8\"><TiffData/></Pixels></Image></OME>";
    const std::string path = dir.path(name);
    EXPECT_TRUE(testing::writeTiff(path, 3, 2, pages, SAMPLEFORMAT_UINT, 1, xml));
    return loadVolume(path);
  };
  const Volume yOnly = open("y.ome.tif", "PhysicalSizeY=\"0.4\" PhysicalSizeZ=\"2\"");
  EXPECT_EQ(yOnly.spacing(), glm::dvec3(0.4, 0.4, 2.0));
  EXPECT_TRUE(testing::hasNoteWith(yOnly, "no pixel width in the file: its height assumed"));
  EXPECT_FALSE(testing::hasNoteWith(yOnly, "no pixel size"));
  const Volume xOnly = open("x.ome.tif", "PhysicalSizeX=\"0.3\" PhysicalSizeZ=\"2\"");
  EXPECT_EQ(xOnly.spacing(), glm::dvec3(0.3, 0.3, 2.0));
  const Volume none = open("none.ome.tif", "PhysicalSizeZ=\"2\"");
  EXPECT_EQ(none.spacing(), glm::dvec3(1.0, 1.0, 2.0));
  EXPECT_TRUE(testing::hasNoteWith(none, "no pixel size in the file: 1 assumed"));
}

}  // namespace
}  // namespace ewa

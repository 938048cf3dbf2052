// OME-TIFF datasets split over several files (by time point, by channel, or by size as
// Micro-Manager splits them): each slice read from the file and page its TiffData names.
#include <gtest/gtest.h>

#include <filesystem>
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
using testing::zctOf;

std::string omeXml(const std::string& order, const std::string& tiffData, int sizeZ = 3) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\" "
         "UUID=\"urn:uuid:1\"><Image ID=\"Image:0\"><Pixels DimensionOrder=\"XY" +
         order + "\" ID=\"Pixels:0\" PhysicalSizeX=\"0.5\" PhysicalSizeZ=\"2\" SizeC=\"2\" " +
         "SizeT=\"2\" SizeX=\"3\" SizeY=\"2\" SizeZ=\"" + std::to_string(sizeZ) +
         "\" Type=\"uint16\"><Channel ID=\"Channel:0:0\"/>" + tiffData + "</Pixels></Image></OME>";
}

std::string block(const std::string& attributes, const std::string& file) {
  return "<TiffData " + attributes + "><UUID FileName=\"" + file + "\">urn:uuid:" + file +
         "</UUID></TiffData>";
}

void expectEveryPlane(const std::string& path) {
  for (int c = 0; c < 2; ++c)
    for (int t = 0; t < 2; ++t) expectPlanes(loadVolume(path, {"", t, c, {}}), c, t);
}

bool writeOme(const std::string& path, const std::vector<std::vector<uint16_t>>& pages,
              const std::string& xml) {
  return testing::writeTiff(path, 3, 2, pages, SAMPLEFORMAT_UINT, 1, xml);
}

TEST(OmeFiles, OneFileATimePoint) {
  TempDir dir;
  const std::string xml =
      omeXml("ZCT", block("FirstT=\"0\" IFD=\"0\" PlaneCount=\"6\"", "t0.ome.tif") +
                        block("FirstT=\"1\" IFD=\"0\" PlaneCount=\"6\"", "t1.ome.tif"));
  ASSERT_TRUE(writeOme(dir.path("t0.ome.tif"), planeRange("ZCT", 0, 6), xml));
  ASSERT_TRUE(writeOme(dir.path("t1.ome.tif"), planeRange("ZCT", 6, 12), xml));
  // Either file opens the whole dataset, and so does their folder.
  expectEveryPlane(dir.path("t0.ome.tif"));
  expectEveryPlane(dir.path("t1.ome.tif"));
  const Volume v = loadVolume(dir.path(""), {"", 1, 0, {}});
  expectPlanes(v, 0, 1);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 0.5, 2.0));
  EXPECT_EQ(v.frameCount(), 2);
  EXPECT_NE(testing::allNotes(v).find("an OME-TIFF dataset: 3 slices from 1 files"),
            std::string::npos)
      << testing::allNotes(v);

  // A time point whose file is missing fails naming it; the other still opens.
  std::filesystem::remove(dir.path("t1.ome.tif"));
  const std::string path = dir.path("t0.ome.tif");
  expectPlanes(loadVolume(path, {"", 0, 1, {}}), 1, 0);
  expectLoadError(
      [&] {
        loadVolume(path, {"", 1, 0, {}});
      },
      path, "the dataset's file 't1.ome.tif' is missing or not a TIFF file");
}

TEST(OmeFiles, SplitBySizeTheRestOfEachFile) {
  // Micro-Manager's way: the planes in order, the first 7 in one file, the rest in the next;
  // the second TiffData gives neither IFD nor PlaneCount: every page of its file.
  TempDir dir;
  const std::string xml =
      omeXml("CZT", block("IFD=\"0\" PlaneCount=\"7\"", "a.ome.tif") +
                        block("FirstC=\"1\" FirstZ=\"0\" FirstT=\"1\"", "b.ome.tif"));
  ASSERT_TRUE(writeOme(dir.path("a.ome.tif"), planeRange("CZT", 0, 7), xml));
  ASSERT_TRUE(writeOme(dir.path("b.ome.tif"), planeRange("CZT", 7, 12), ""));
  expectEveryPlane(dir.path("a.ome.tif"));
  EXPECT_NE(testing::allNotes(loadVolume(dir.path("a.ome.tif"), {"", 1, 0, {}}))
                .find("3 slices from 2 files"),
            std::string::npos);
}

TEST(OmeFiles, OneTiffDataAPlaneOneFileAChannel) {
  TempDir dir;
  std::string blocks;
  std::vector<std::vector<uint16_t>> pages[2];
  for (int p = 0; p < 12; ++p) {
    const auto [z, c, t] = zctOf("TZC", p);
    const std::string file = "ch" + std::to_string(c) + ".ome.tif";
    blocks += block("FirstZ=\"" + std::to_string(z) + "\" FirstC=\"" + std::to_string(c) +
                        "\" FirstT=\"" + std::to_string(t) + "\" IFD=\"" +
                        std::to_string(pages[c].size()) + "\" PlaneCount=\"1\"",
                    file);
    pages[c].push_back(planeRange("TZC", p, p + 1)[0]);
  }
  const std::string xml = omeXml("TZC", blocks);
  ASSERT_TRUE(writeOme(dir.path("ch0.ome.tif"), pages[0], xml));
  ASSERT_TRUE(writeOme(dir.path("ch1.ome.tif"), pages[1], xml));
  expectEveryPlane(dir.path("ch1.ome.tif"));
}

TEST(OmeFiles, CompanionMetadataFile) {
  // Bio-Formats' companion form: the XML in cells.companion.ome, each TIFF naming it.
  TempDir dir;
  const std::string binaryOnly =
      "<?xml version=\"1.0\"?><OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\">"
      "<BinaryOnly MetadataFile=\"cells.companion.ome\" UUID=\"urn:uuid:1\"/></OME>";
  ASSERT_TRUE(writeOme(dir.path("t0.ome.tif"), planeRange("ZCT", 0, 6), binaryOnly));
  ASSERT_TRUE(writeOme(dir.path("t1.ome.tif"), planeRange("ZCT", 6, 12), binaryOnly));
  const std::string companion =
      dir.write("cells.companion.ome",
                omeXml("ZCT", block("FirstT=\"0\" IFD=\"0\" PlaneCount=\"6\"", "t0.ome.tif") +
                                  block("FirstT=\"1\" IFD=\"0\" PlaneCount=\"6\"", "t1.ome.tif")));
  expectEveryPlane(companion);
  expectEveryPlane(dir.path("t1.ome.tif"));
  const Volume v = loadVolume(dir.path(""), {"", 1, 1, {}});
  expectPlanes(v, 1, 1);
  EXPECT_EQ(v.spacing(), glm::dvec3(0.5, 0.5, 2.0));
  EXPECT_EQ(v.channelCount(), 2);

  dir.write("cells.companion.ome", "<OME><Image/></OME>");
  expectLoadError([&] { loadVolume(companion); }, companion, "no OME-XML Pixels element");
  dir.write("cells.companion.ome", omeXml("ZCT", "<TiffData/>"));
  expectLoadError([&] { loadVolume(companion); }, companion, "names no TIFF file");
  std::filesystem::remove(companion);
  const std::string t0 = dir.path("t0.ome.tif");
  expectLoadError([&] { loadVolume(t0); }, t0,
                  "its OME metadata file 'cells.companion.ome' is missing");
  const std::string away = dir.path("away.ome.tif");
  ASSERT_TRUE(writeOme(away, planeRange("ZCT", 0, 6),
                       "<OME><BinaryOnly MetadataFile=\"../cells.companion.ome\"/></OME>"));
  expectLoadError([&] { loadVolume(away); }, away, "not a file beside it");
}

TEST(OmeFiles, BadDatasetsFailInOneLine) {
  TempDir dir;
  const std::string a = dir.path("a.ome.tif");
  ASSERT_TRUE(writeOme(a, planeRange("ZCT", 0, 6),
                       omeXml("ZCT", block("PlaneCount=\"6\"", "a.ome.tif") +
                                         block("FirstT=\"1\"", "../b.ome.tif"))));
  expectLoadError([&] { loadVolume(a); }, a, "a TiffData names '../b.ome.tif', not a file beside");

  // SizeZ 4: the file's 6 pages hold channel 0's 4 slices and 2 of channel 1's.
  const std::string c = dir.path("c.ome.tif");
  ASSERT_TRUE(
      writeOme(c, planeRange("ZCT", 0, 6),
               omeXml("ZCT", block("", "c.ome.tif") + block("FirstT=\"1\"", "d.ome.tif"), 4)));
  EXPECT_EQ(loadVolume(c).dims()[2], 4);
  expectLoadError(
      [&] {
        loadVolume(c, {"", 0, 1, {}});
      },
      c, "slice 2 of channel 1, time point 0 is in none of the OME-TIFF dataset's files");

  // The second file's pages are another size.
  const std::string e = dir.path("e.ome.tif"), f = dir.path("f.ome.tif");
  const std::string xml =
      omeXml("ZCT", block("PlaneCount=\"6\"", "e.ome.tif") + block("FirstT=\"1\"", "f.ome.tif"));
  ASSERT_TRUE(writeOme(e, planeRange("ZCT", 0, 6), xml));
  ASSERT_TRUE(testing::writeTiff(f, 2, 3, planeRange("ZCT", 6, 12), SAMPLEFORMAT_UINT, 1, xml));
  expectLoadError([&] { loadVolume(e, {"", 1, 0, {}}); }, e, "all pages must agree");
}

TEST(OmeFiles, PlaneSourcesAreBoundedByThePagesFilesHold) {
  // A hostile PlaneCount and SizeZ: only the pages the file has are visited, and no slice list
  // is sized by SizeZ.
  TiffPlaneOrder o;
  o.kind = "OME";
  o.order = "ZCT";
  o.slices = int64_t(1) << 30;
  o.channels = 1;
  o.frames = 1;
  o.blocks.push_back({"b.tif", 2, 0, 0, 0, int64_t(1) << 30, true});
  int calls = 0;
  const auto sources = omePlaneSources("/data/a.tif", o, 0, 0, [&](const std::string& file) {
    EXPECT_EQ(file, "/data/b.tif");
    ++calls;
    return int64_t(5);
  });
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(sources.size(), 3u);  // pages 2, 3, 4
  EXPECT_EQ(sources.at(0).ifd, 2);
  EXPECT_EQ(sources.at(2).ifd, 4);
  EXPECT_EQ(sources.at(2).file, "/data/b.tif");
}

TEST(OmeFiles, DescriptionsKeepTheirTiffDataOnlyWhenTheyNameAnotherFile) {
  const std::string self = omeXml("ZCT", block("", "a.ome.tif") + "<TiffData IFD=\"3\"/>");
  EXPECT_TRUE(tiffPlaneOrder("/x/a.ome.tif", self, 1).blocks.empty());
  const TiffPlaneOrder other = tiffPlaneOrder(
      "/x/a.ome.tif",
      omeXml("ZCT", "<TiffData IFD=\"3\"/>" + block("FirstT=\"1\" PlaneCount=\"6\"", "b.ome.tif")),
      1);
  ASSERT_EQ(other.blocks.size(), 2u);
  EXPECT_EQ(other.blocks[0].file, "");
  EXPECT_EQ(other.blocks[0].ifd, 3);
  EXPECT_TRUE(other.blocks[0].ifdGiven);
  EXPECT_EQ(other.blocks[0].planeCount, -1);
  EXPECT_EQ(other.blocks[1].file, "b.ome.tif");
  EXPECT_EQ(other.blocks[1].firstT, 1);
  EXPECT_EQ(other.blocks[1].planeCount, 6);
  EXPECT_FALSE(other.blocks[1].ifdGiven);
}

}  // namespace
}  // namespace ewa

// Loader tests on broken input: each must fail with a one-line LoadError naming the file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::bytesOf;
using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::gzipBytes;
using testing::TempDir;
using testing::uintBytes;
using testing::zlibBytes;

const std::string kData24(24, '\x05');

std::string nrrd(const std::string& fields) {
  return "NRRD0004\n" + fields;
}
const std::string kGoodFields = "type: uchar\ndimension: 3\nsizes: 2 3 4\nencoding: raw\n";

TEST(LoaderErrors, MissingFileAndDirectory) {
  TempDir dir;
  expectVolumeLoadError(dir.path("nothing.nrrd"), "no such file");
  expectVolumeLoadError(dir.path("nothing.vti"), "no such file");
  std::filesystem::create_directory(dir.path("folder.nrrd"));
  expectVolumeLoadError(dir.path("folder.nrrd"), "directory");
  expectLoadError(
      [&] { loadRawVolume(dir.path("folder.nrrd"), parseRawOptions("1,1,1", "", "", "")); },
      dir.path("folder.nrrd"), "directory");
  expectVolumeLoadError(dir.path("missing/x.mhd"), "no such file");
  expectVolumeLoadError("", "empty file name");
}

TEST(LoaderErrors, FifoDoesNotHang) {
  TempDir dir;
  ASSERT_EQ(mkfifo(dir.path("pipe.nrrd").c_str(), 0600), 0);
  expectVolumeLoadError(dir.path("pipe.nrrd"), "not a regular file");
}

TEST(LoaderErrors, UnknownExtension) {
  TempDir dir;
  expectVolumeLoadError(dir.write("v.xyz", "hello"), "unknown volume file extension");
  expectVolumeLoadError(dir.write("v.raw", kData24), "raw files need");
}

TEST(LoaderErrors, NrrdTruncatedAndTooLargeSizes) {
  TempDir dir;
  expectVolumeLoadError(dir.write("trunc.nrrd", nrrd(kGoodFields + "\n") + kData24.substr(0, 23)),
                        "truncated");
  expectVolumeLoadError(
      dir.write("big.nrrd",
                nrrd("type: uchar\ndimension: 3\nsizes: 2 3 400\nencoding: raw\n\n") + kData24),
      "truncated");
  expectVolumeLoadError(
      dir.write("overflow.nrrd", nrrd("type: float\ndimension: 3\nsizes: 4294967296 4294967296 "
                                      "4294967296\nencoding: raw\n\n")),
      "overflow");
  expectVolumeLoadError(
      dir.write(
          "int64.nrrd",
          nrrd("type: uchar\ndimension: 3\nsizes: 9223372036854775807 2 1\nencoding: raw\n\n")),
      "too large");
  expectVolumeLoadError(
      dir.write(
          "toolong.nrrd",
          nrrd("type: uchar\ndimension: 3\nsizes: 99999999999999999999 2 1\nencoding: raw\n\n")),
      "bad sizes");
  expectVolumeLoadError(
      dir.write(
          "huge.nrrd",
          nrrd("type: uchar\ndimension: 3\nsizes: 1000000 1000000 1000000\nencoding: raw\n\n") +
              kData24),
      "memory");
  // A huge gzip claim with a tiny stream must fail before allocating anything large.
  expectVolumeLoadError(
      dir.write("hugegz.nrrd",
                nrrd("type: uchar\ndimension: 3\nsizes: 1000 1000 100\nencoding: gzip\n\n") +
                    gzipBytes(kData24)),
      "cannot inflate");
}

TEST(LoaderErrors, NrrdBadSizesText) {
  TempDir dir;
  const std::pair<const char*, const char*> cases[] = {{"0 3 4", "must all be positive"},
                                                       {"2 -3 4", "must all be positive"},
                                                       {"2 abc 4", "bad sizes"},
                                                       {"2 3.5 4", "bad sizes"},
                                                       {"2 3", "has 2 values"},
                                                       {"2 3 4 5", "has 4 values"},
                                                       {"", "missing sizes"}};
  for (const auto& [sizes, problem] : cases) {
    const std::string path = dir.write(
        "s.nrrd",
        nrrd("type: uchar\ndimension: 3\nsizes: " + std::string(sizes) + "\nencoding: raw\n\n") +
            kData24);
    SCOPED_TRACE(sizes);
    expectVolumeLoadError(path, problem);
  }
}

TEST(LoaderErrors, NrrdUnknownOrUnsupportedTypeAndEncoding) {
  TempDir dir;
  const std::string tail = "dimension: 3\nsizes: 2 3 4\n";
  expectVolumeLoadError(
      dir.write("t1.nrrd", nrrd("type: quux\nencoding: raw\n" + tail + "\n") + kData24),
      "unknown type");
  expectVolumeLoadError(
      dir.write("t2.nrrd", nrrd("type: block\nencoding: raw\n" + tail + "\n") + kData24),
      "unsupported type 'block'");
  expectVolumeLoadError(  // 24 int32 values need 96 bytes
      dir.write("t3.nrrd", nrrd("type: int32\nencoding: raw\n" + tail + "\n") + kData24),
      "data needs 96 bytes");
  expectVolumeLoadError(
      dir.write("e1.nrrd", nrrd("type: uchar\nencoding: zip\n" + tail + "\n") + kData24),
      "unknown encoding");
  expectVolumeLoadError(
      dir.write("e2.nrrd", nrrd("type: uchar\nencoding: zrl\n" + tail + "\n") + kData24),
      "unsupported encoding 'zrl'");
  expectVolumeLoadError(dir.write("e3.nrrd", nrrd("type: uchar\n" + tail + "\n") + kData24),
                        "missing encoding");
  expectVolumeLoadError(
      dir.write("d5.nrrd",
                nrrd("type: uchar\nencoding: raw\ndimension: 5\nsizes: 1 2 3 4 1\n\n") + kData24),
      "unsupported dimension '5'");
  expectVolumeLoadError(dir.write("en.nrrd", nrrd(kGoodFields + "endian: middle\n\n") + kData24),
                        "endian");
  expectVolumeLoadError(dir.write("bs.nrrd", nrrd(kGoodFields + "byte skip: -2\n\n") + kData24),
                        "byte skip");
}

TEST(LoaderErrors, NrrdMissingDataFiles) {
  TempDir dir;
  expectVolumeLoadError(dir.write("m1.nhdr", nrrd(kGoodFields + "data file: absent.raw\n")),
                        "absent.raw: no such file");
  dir.write("one.raw", kData24.substr(0, 12));
  expectVolumeLoadError(
      dir.write("m2.nhdr", nrrd(kGoodFields + "data file: LIST\none.raw\ntwo.raw\n")),
      "two.raw: no such file");
  expectVolumeLoadError(dir.write("m3.nhdr", nrrd(kGoodFields + "data file: s%d.raw 1 4 1\n")),
                        "no such file");
  expectVolumeLoadError(dir.write("m4.nhdr", nrrd(kGoodFields)), "no data file");
  std::filesystem::create_directory(dir.path("sub"));
  expectVolumeLoadError(dir.write("m5.nhdr", nrrd(kGoodFields + "data file: sub\n")), "directory");
  expectVolumeLoadError(dir.write("m6.nhdr", nrrd(kGoodFields + "data file: one.raw\n")),
                        "truncated");
  expectVolumeLoadError(
      dir.write("m7.nhdr", nrrd(kGoodFields + "line skip: 5\ndata file: one.raw\n")), "line skip");
}

TEST(LoaderErrors, NrrdBadDataFilePatterns) {
  TempDir dir;
  expectVolumeLoadError(dir.write("p1.nhdr", nrrd(kGoodFields + "data file: s%s.raw 1 4 1\n")),
                        "pattern");
  expectVolumeLoadError(dir.write("p2.nhdr", nrrd(kGoodFields + "data file: s%n%d.raw 1 4 1\n")),
                        "pattern");
  expectVolumeLoadError(dir.write("p3.nhdr", nrrd(kGoodFields + "data file: s%d%d.raw 1 4 1\n")),
                        "pattern");
  expectVolumeLoadError(dir.write("p4.nhdr", nrrd(kGoodFields + "data file: s%d.raw 1 4 0\n")),
                        "range");
  expectVolumeLoadError(dir.write("p5.nhdr", nrrd(kGoodFields + "data file: s%d.raw 4 1 1\n")),
                        "range");
  expectVolumeLoadError(
      dir.write("p6.nhdr", nrrd(kGoodFields +
                                "data file: s%d.raw -9223372036854775807 9223372036854775807 1\n")),
      "too many");
  expectVolumeLoadError(dir.write("p7.nhdr", nrrd(kGoodFields + "data file: s%d.raw 1 5 1\n")),
                        "split");
  expectVolumeLoadError(
      dir.write("p8.nhdr", nrrd(kGoodFields + "data file: s%999999d.raw 1 4 1\n")), "width");
  expectVolumeLoadError(dir.write("p9.nhdr", nrrd(kGoodFields + "data file: LIST\n")), "LIST");
}

TEST(LoaderErrors, NrrdCorruptGzip) {
  TempDir dir;
  const std::string head = nrrd("type: uchar\ndimension: 3\nsizes: 2 3 4\nencoding: gzip\n\n");
  const std::string good = gzipBytes(kData24);
  expectVolumeLoadError(dir.write("g1.nrrd", head + "this is not gzip data at all"), "corrupt");
  expectVolumeLoadError(dir.write("g2.nrrd", head + good.substr(0, good.size() / 2)), "gzip");
  expectVolumeLoadError(dir.write("g3.nrrd", head + good.substr(0, good.size() - 4)), "truncated");
  expectVolumeLoadError(dir.write("g4.nrrd", head + gzipBytes(kData24 + "x")), "more than");
  expectVolumeLoadError(dir.write("g5.nrrd", head + gzipBytes(kData24.substr(1))), "only 23");
  // Bytes after a complete stream are ignored, as NRRD readers do.
  EXPECT_NO_THROW(loadVolume(dir.write("g6.nrrd", head + good + "trailing junk")));
  std::string flipped = good;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x55);
  expectVolumeLoadError(dir.write("g7.nrrd", head + flipped), "corrupt");
  expectVolumeLoadError(dir.write("g8.nrrd", head), "inflates to only 0 bytes");
}

TEST(LoaderErrors, GarbageTextInEveryFormat) {
  TempDir dir;
  const std::string garbage = "Lorem ipsum dolor sit amet\n\x01\x02\xff\xfe\n<<<>>>\n= : = :\n";
  // Each format names what is wrong: {extension, for garbage, for an empty file}.
  const std::vector<std::array<std::string, 3>> cases = {
      {".nrrd", "not a NRRD file", "not a NRRD file"},
      {".nhdr", "not a NRRD file", "not a NRRD file"},
      {".mhd", "malformed header line", "no ElementDataFile"},
      {".mha", "malformed header line", "no ElementDataFile"},
      {".dat", "malformed header line", "missing ObjectFileName"},
      {".vti", "malformed XML", "not a VTK XML file"}};
  for (const auto& [ext, garbageProblem, emptyProblem] : cases) {
    SCOPED_TRACE(ext);
    expectVolumeLoadError(dir.write("garbage" + ext, garbage), garbageProblem);
    expectVolumeLoadError(dir.write("empty" + ext, ""), emptyProblem);
  }
}

TEST(LoaderErrors, MetaImageProblems) {
  TempDir dir;
  const std::string base = "NDims = 3\nDimSize = 2 3 4\n";
  expectVolumeLoadError(
      dir.write("a.mhd", base + "ElementType = MET_FLOAT_MATRIX\nElementDataFile = x.raw\n"),
      "unsupported ElementType");
  expectVolumeLoadError(dir.write("b.mhd", base + "ElementType = FOO\nElementDataFile = x.raw\n"),
                        "unknown ElementType");
  expectVolumeLoadError(
      dir.write("c.mhd", base + "ElementType = MET_UCHAR\nElementDataFile = x.raw\n"),
      "x.raw: no such file");
  expectVolumeLoadError(
      dir.write("d.mhd",
                "NDims = 4\nDimSize = 2 3 4 1\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n"),
      "NDims");
  expectVolumeLoadError(
      dir.write("e.mhd",
                "NDims = 3\nDimSize = 2 3\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n"),
      "DimSize");
  expectVolumeLoadError(
      dir.write("f.mha",
                base + "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + kData24.substr(5)),
      "truncated");
  const std::string packed = zlibBytes(kData24);
  expectVolumeLoadError(
      dir.write("g.mha",
                base +
                    "ElementType = MET_UCHAR\nCompressedData = True\nCompressedDataSize = 99999\n"
                    "ElementDataFile = LOCAL\n" +
                    packed),
      "CompressedDataSize");
  expectVolumeLoadError(
      dir.write("h.mha",
                base + "ElementType = MET_UCHAR\nCompressedData = True\nElementDataFile = LOCAL\n" +
                    std::string(40, 'Q')),
      "corrupt");
  expectVolumeLoadError(dir.write("i.mha",
                                  "NDims = 3\nDimSize = 4294967296 4294967296 4294967296\n"
                                  "ElementType = MET_FLOAT\nElementDataFile = LOCAL\n"),
                        "overflow");
  expectVolumeLoadError(
      dir.write("j.mhd", base + "ElementType = MET_UCHAR\nElementDataFile = LIST\na\nb\n"),
      "unsupported ElementDataFile");
  expectVolumeLoadError(dir.write("k.mha", base + "ElementType = MET_UCHAR\nElementDataFile =\n"),
                        "empty");
  expectVolumeLoadError(
      dir.write("l.mha",
                base +
                    "ElementType = MET_UCHAR\nElementSpacing = 1 0 1\nElementDataFile = LOCAL\n" +
                    kData24),
      "spacing");
}

TEST(LoaderErrors, DatProblems) {
  TempDir dir;
  dir.write("d.raw", kData24);
  expectVolumeLoadError(
      dir.write("a.dat", "ObjectFileName: d.raw\nResolution: 2 3 4\nFormat: DOUBLE\n"),
      "unsupported Format");
  expectVolumeLoadError(
      dir.write("b.dat", "ObjectFileName: d.raw\nResolution: 2 3 4\nFormat: WIDGET\n"),
      "unknown Format");
  expectVolumeLoadError(dir.write("c.dat", "ObjectFileName: d.raw\nFormat: UCHAR\n"), "Resolution");
  expectVolumeLoadError(
      dir.write("e.dat", "ObjectFileName: nope.raw\nResolution: 2 3 4\nFormat: UCHAR\n"),
      "nope.raw: no such file");
  expectVolumeLoadError(
      dir.write("f.dat", "ObjectFileName: d.raw\nResolution: 2 3 5\nFormat: UCHAR\n"), "truncated");
  expectVolumeLoadError(
      dir.write("g.dat", "ObjectFileName: d.raw\nResolution: 2 -3 4\nFormat: UCHAR\n"), "positive");
  expectVolumeLoadError(
      dir.write("h.dat",
                "ObjectFileName: d.raw\nResolution: 2 3 4\nFormat: UCHAR\nByteOrder: Sideways\n"),
      "ByteOrder");
}

TEST(LoaderErrors, VtiProblems) {
  TempDir dir;
  auto vti = [](const std::string& fileAttrs, const std::string& arrayAttrs,
                const std::string& appended, const std::string& extent = "0 1 0 2 0 3") {
    return "<VTKFile type=\"ImageData\" " + fileAttrs + "><ImageData WholeExtent=\"" + extent +
           "\" Origin=\"0 0 0\" Spacing=\"1 1 1\"><Piece Extent=\"" + extent +
           "\"><PointData><DataArray Name=\"a\" " + arrayAttrs +
           "/></PointData></Piece></ImageData><AppendedData encoding=\"raw\">_" + appended +
           "</AppendedData></VTKFile>";
  };
  const std::string raw = uintBytes(24, 4) + kData24;
  const std::string ok = "type=\"UInt8\" format=\"appended\" offset=\"0\"";
  // Sanity: the good form loads.
  EXPECT_NO_THROW(loadVolume(dir.write("ok.vti", vti("", ok, raw))));
  expectVolumeLoadError(
      dir.write("a.vti", vti("", "type=\"String\" format=\"appended\" offset=\"0\"", raw)),
      "unsupported DataArray type");
  expectVolumeLoadError(dir.write("b.vti", vti("header_type=\"UInt16\"", ok, raw)), "header_type");
  expectVolumeLoadError(dir.write("c.vti", vti("compressor=\"vtkLZ4DataCompressor\"", ok, raw)),
                        "compressor");
  expectVolumeLoadError(dir.write("d.vti", vti("", ok + " NumberOfComponents=\"3\"", raw)),
                        "the extent needs 72");  // three components of 24 points
  expectVolumeLoadError(dir.write("d2.vti", vti("", ok + " NumberOfComponents=\"0\"", raw)),
                        "0 components a voxel (1 to 4096 are read)");
  expectVolumeLoadError(dir.write("e.vti", vti("", ok, raw, "0 1 5 2 0 3")), "extent");
  expectVolumeLoadError(
      dir.write("f.vti", vti("", "type=\"UInt8\" format=\"appended\" offset=\"999999\"", raw)),
      "points past the end");
  expectVolumeLoadError(dir.write("g.vti", vti("", ok, uintBytes(25, 4) + kData24)),
                        "holds 25 bytes");
  const std::string cut = vti("", ok, raw);
  expectVolumeLoadError(dir.write("h.vti", cut.substr(0, cut.find('_') + 1 + 4 + 10)), "truncated");
  expectVolumeLoadError(dir.write("i.vti", vti("", "type=\"UInt8\" format=\"ascii\"", "")),
                        "ASCII DataArray cannot hold 24 values in its 0 bytes");
  expectVolumeLoadError(dir.write("i2.vti", vti("", "type=\"UInt8\" format=\"text\"", "")),
                        "unsupported DataArray format 'text'");
  expectVolumeLoadError(dir.write("j.vti", "<VTKFile type=\"PolyData\"></VTKFile>"),
                        "not ImageData");
  expectVolumeLoadError(
      dir.write("k.vti", "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 1"),
      "unterminated value");
  expectVolumeLoadError(dir.write("l.vti", "<VTKFile type=\"ImageData\" a=b></VTKFile>"), "quoted");
  expectVolumeLoadError(
      dir.write("m.vti", vti("", ok, raw, "0 4294967295 0 4294967295 0 4294967295")), "overflow");
  const std::string zl = "compressor=\"vtkZLibDataCompressor\"";
  // nblocks far beyond the data, a block table that overflows, compressed sizes past the end.
  expectVolumeLoadError(
      dir.write("n.vti",
                vti(zl, ok, uintBytes(0xffffffffu, 4) + uintBytes(24, 4) + uintBytes(0, 4))),
      "blocks");
  const std::string packed = zlibBytes(kData24);
  expectVolumeLoadError(
      dir.write("o.vti", vti(zl, ok,
                             uintBytes(1, 4) + uintBytes(24, 4) + uintBytes(0, 4) +
                                 uintBytes(packed.size() + 1000, 4) + packed)),
      "truncated");
  expectVolumeLoadError(
      dir.write("p.vti", vti(zl, ok,
                             uintBytes(1, 4) + uintBytes(24, 4) + uintBytes(0, 4) +
                                 uintBytes(packed.size(), 4) + std::string(packed.size(), 'x'))),
      "corrupt");
  expectVolumeLoadError(dir.write("q.vti", vti(zl, ok,
                                               uintBytes(2, 4) + uintBytes(24, 4) +
                                                   uintBytes(0, 4) + uintBytes(packed.size(), 4) +
                                                   uintBytes(packed.size(), 4) + packed + packed)),
                        "does not hold");
  expectVolumeLoadError(dir.write("r.vti", vti("", "type=\"UInt8\" format=\"binary\"", "")),
                        "decoded data has only 0 bytes");
}

TEST(LoaderErrors, RawOptionsAndRawFiles) {
  expectLoadError([] { parseRawOptions("", "uint8", "", ""); }, "--raw-dims", "missing");
  expectLoadError([] { parseRawOptions("1,2", "uint8", "", ""); }, "--raw-dims", "three sizes");
  expectLoadError([] { parseRawOptions("1,0,2", "uint8", "", ""); }, "--raw-dims", "positive");
  expectLoadError([] { parseRawOptions("1,a,2", "uint8", "", ""); }, "--raw-dims", "integers");
  expectLoadError([] { parseRawOptions("1,2,3", "complex", "", ""); }, "--raw-type",
                  "unknown type");
  expectLoadError([] { parseRawOptions("1,2,3", "uint8", "1,x,1", ""); }, "--raw-spacing",
                  "numbers");
  expectLoadError([] { parseRawOptions("1,2,3", "uint8", "1,-1,1", ""); }, "--raw-spacing",
                  "positive");
  expectLoadError([] { parseRawOptions("1,2,3", "uint8", "1,1", ""); }, "--raw-spacing",
                  "one value");
  expectLoadError([] { parseRawOptions("1,2,3", "uint8", "", "middle"); }, "--raw-endian",
                  "little or big");
  TempDir dir;
  const std::string path = dir.write("r.raw", kData24);
  expectLoadError([&] { loadRawVolume(path, parseRawOptions("2,3,5", "uint8", "", "")); }, path,
                  "truncated");
  expectLoadError(
      [&] {
        loadRawVolume(path, parseRawOptions("4294967296,4294967296,4294967296", "float", "", ""));
      },
      path, "overflow");
  expectLoadError(
      [&] { loadRawVolume(dir.path("none.raw"), parseRawOptions("2,3,4", "", "", "")); },
      dir.path("none.raw"), "no such file");
  RawOptions bad;
  bad.dims = {2, 0, 3};
  expectLoadError([&] { loadRawVolume(path, bad); }, path, "positive");
}

// Every truncation and many random byte changes of small valid files: each load must either
// succeed or throw LoadError (run under -DEWA_SANITIZE=ON to catch memory errors too).
TEST(LoaderErrors, TruncatedAndMutatedFilesNeverCrash) {
  TempDir dir;
  const std::string values = bytesOf(std::vector<uint16_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
  auto blocks = [&](const std::string& data) {
    const std::string z = zlibBytes(data);
    return uintBytes(1, 8) + uintBytes(data.size(), 8) + uintBytes(0, 8) + uintBytes(z.size(), 8) +
           z;
  };
  const std::vector<std::pair<std::string, std::string>> samples = {
      {"s.nrrd",
       "NRRD0004\ntype: ushort\ndimension: 3\nsizes: 2 3 2\nendian: big\nencoding: gzip\n"
       "space directions: (1,0,0) (0,2,0) (0,0,3)\nspace origin: (1,2,3)\n\n" +
           gzipBytes(values)},
      {"s.mha",
       "NDims = 3\nDimSize = 2 3 2\nElementType = MET_USHORT\nCompressedData = True\n"
       "ElementDataFile = LOCAL\n" +
           zlibBytes(values)},
      {"s.vti",
       "<VTKFile type=\"ImageData\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">"
       "<ImageData WholeExtent=\"0 1 0 2 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\"><Piece "
       "Extent=\"0 1 0 2 0 1\">"
       "<PointData Scalars=\"v\"><DataArray type=\"UInt16\" Name=\"v\" format=\"appended\" "
       "offset=\"0\"/>"
       "</PointData></Piece></ImageData><AppendedData encoding=\"raw\">_" +
           blocks(values) + "</AppendedData></VTKFile>"},
      {"s.dat",
       "ObjectFileName: s.bin\nResolution: 2 3 2\nSliceThickness: 1 1 1\nFormat: USHORT\n"},
  };
  dir.write("s.bin", values);
  std::mt19937 rng(12345);
  int loaded = 0, failed = 0;
  auto attempt = [&](const std::string& path) {
    try {
      loadVolume(path);
      ++loaded;
    } catch (const LoadError& e) {
      ++failed;
      ASSERT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
  };
  for (const auto& [name, bytes] : samples) {
    SCOPED_TRACE(name);
    ASSERT_NO_THROW(loadVolume(dir.write(name, bytes)));
    for (size_t n = 0; n < bytes.size(); ++n) attempt(dir.write(name, bytes.substr(0, n)));
    for (int round = 0; round < 300; ++round) {
      std::string mutated = bytes;
      const int changes = 1 + static_cast<int>(rng() % 3);
      for (int c = 0; c < changes; ++c) {
        mutated[rng() % mutated.size()] =
            static_cast<char>(rng() % 4 == 0 ? "0123456789 \n-"[rng() % 13] : rng());
      }
      attempt(dir.write(name, mutated));
    }
  }
  EXPECT_GT(failed, 0);
  EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace ewa

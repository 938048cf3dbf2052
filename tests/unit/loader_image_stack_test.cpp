// Image stacks: folders of PNG (8 and 16 bits, grey, grey and alpha, colour), PGM/PPM and BMP
// slices in natural name order; colour channels; bad and mismatched images fail in one line.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/volume_loader.h"
#include "loader_test_files.h"

namespace ewa {
namespace {

using testing::expectLoadError;
using testing::expectVolumeLoadError;
using testing::TempDir;

std::string bigEndian32(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string pngChunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  const auto crc =
      uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size())));
  return bigEndian32(uint32_t(data.size())) + body + bigEndian32(crc);
}

// A PNG of `width` x `height` pixels of `components` samples (1 grey, 2 grey and alpha, 3 RGB),
// `bits` 8 or 16 (stored big-endian, as PNG does), from `samples` row by row.
std::string pngBytes(int width, int height, int components, int bits,
                     const std::vector<uint16_t>& samples) {
  static const char kColourType[] = {0, 0, 4, 2, 6};
  std::string header = bigEndian32(uint32_t(width)) + bigEndian32(uint32_t(height));
  header += {char(bits), kColourType[components], 0, 0, 0};
  std::string rows;
  size_t at = 0;
  for (int y = 0; y < height; ++y) {
    rows += '\0';  // filter: none
    for (int x = 0; x < width * components; ++x, ++at) {
      if (bits == 16) rows += char(samples[at] >> 8);
      rows += char(samples[at] & 0xff);
    }
  }
  return "\x89PNG\r\n\x1a\n" + pngChunk("IHDR", header) +
         pngChunk("IDAT", testing::zlibBytes(rows)) + pngChunk("IEND", "");
}

// A binary PGM (components 1) or PPM (3) of 8-bit samples.
std::string pnmBytes(int width, int height, int components, const std::vector<uint16_t>& samples) {
  std::string out = std::string(components == 1 ? "P5" : "P6") + " " + std::to_string(width) + " " +
                    std::to_string(height) + " 255\n";
  for (uint16_t s : samples) out += char(s);
  return out;
}

// 3 x 2 pixels of slice z: sample c of pixel i is 40 z + 10 i + c (times 300 for 16 bits).
std::vector<uint16_t> slice(int z, int components, int scale = 1) {
  std::vector<uint16_t> v;
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < components; ++c) v.push_back(uint16_t(scale * (40 * z + 10 * i + c)));
  return v;
}

TEST(ImageStack, PngSlicesInNaturalOrderFromTheFolderOrAnyOfItsImages) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("s"));
  const int order[] = {2, 0, 1};  // written as z1, z10, z2: natural order puts z10 last
  const char* names[] = {"s/z10.png", "s/z1.png", "s/z2.png"};
  for (int n = 0; n < 3; ++n) dir.write(names[n], pngBytes(3, 2, 1, 8, slice(order[n], 1)));
  dir.write("s/notes.txt", "not a slice");
  dir.write("s/._z1.png", "macOS's resource fork of z1.png, not an image");
  for (const std::string& path : {dir.path("s"), dir.path("s/z2.png")}) {
    const Volume v = loadVolume(path);
    EXPECT_EQ(v.dims(), (std::array<int64_t, 3>{3, 2, 3}));
    EXPECT_EQ(v.type(), ScalarType::UInt8);
    for (int z = 0; z < 3; ++z)
      for (int i = 0; i < 6; ++i) ASSERT_EQ(v.value(i % 3, i / 3, z), 40 * z + 10 * i) << path;
    EXPECT_EQ(v.spacing(), glm::dvec3(1.0));
    EXPECT_EQ(v.notes().front(),
              "3 images as slices, in name order; images carry no slice spacing: 1 assumed");
  }
}

TEST(ImageStack, SixteenBitGreyAndAlphaAndGreyStoredAsColour) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("a"));
  for (int z = 0; z < 2; ++z)
    dir.write("a/" + std::to_string(z) + ".png", pngBytes(3, 2, 1, 16, slice(z, 1, 300)));
  const Volume a = loadVolume(dir.path("a"));
  EXPECT_EQ(a.type(), ScalarType::UInt16);
  EXPECT_EQ(a.value(2, 1, 1), 300 * (40 + 50));
  // Grey and alpha: the grey.
  std::filesystem::create_directories(dir.path("b"));
  dir.write("b/0.png", pngBytes(3, 2, 2, 8, slice(1, 2)));
  EXPECT_EQ(loadVolume(dir.path("b")).value(1, 0, 0), 40 + 10);
  // Colour images whose channels agree everywhere: grey, one channel.
  std::vector<uint16_t> grey;
  for (uint16_t s : slice(2, 1)) grey.insert(grey.end(), {s, s, s});
  std::filesystem::create_directories(dir.path("c"));
  dir.write("c/0.ppm", pnmBytes(3, 2, 3, grey));
  const Volume c = loadVolume(dir.path("c"));
  EXPECT_EQ(c.channelCount(), 1);
  EXPECT_EQ(c.value(0, 1, 0), 80 + 30);
  EXPECT_EQ(c.notes().back(), "grey images stored as colour: one channel read");
}

TEST(ImageStack, ColourImagesOpenOneChannelAtATime) {
  TempDir dir;
  for (int z = 0; z < 2; ++z)
    dir.write("rgb" + std::to_string(z) + ".ppm", pnmBytes(3, 2, 3, slice(z, 3)));
  for (int c = 0; c < 3; ++c) {
    const Volume v = loadVolume(dir.path("rgb0.ppm"), {"", 0, c, {}});
    EXPECT_EQ(v.channelCount(), 3);
    EXPECT_EQ(v.channel(), c);
    EXPECT_EQ(v.value(1, 1, 1), 40 + 40 + c);
  }
  expectLoadError(
      [&] {
        loadVolume(dir.path("rgb0.ppm"), {"", 0, 3, {}});
      },
      dir.path("rgb0.ppm"), "--channel 3 is out of range (3 channels)");
}

TEST(ImageStack, MismatchedBrokenAndForeignImagesFailInOneLine) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("m"));
  dir.write("m/1.png", pngBytes(3, 2, 1, 8, slice(0, 1)));
  dir.write("m/2.png", pngBytes(2, 3, 1, 8, slice(1, 1)));
  expectVolumeLoadError(dir.path("m"),
                        "is 2 x 3 grey 8-bit, the first image (1.png) 3 x 2 grey "
                        "8-bit: all slices must agree");
  std::filesystem::create_directories(dir.path("d"));
  dir.write("d/1.png", pngBytes(3, 2, 1, 16, slice(0, 1)));
  dir.write("d/2.png", pngBytes(3, 2, 1, 8, slice(1, 1)));
  expectVolumeLoadError(dir.path("d"), "all slices must agree");
  std::filesystem::create_directories(dir.path("x"));
  dir.write("x/a.png", "this is not a PNG at all");
  expectVolumeLoadError(dir.path("x/a.png"), "not a PNG, JPEG, BMP or binary PGM/PPM image");
  // A GIF (which stb_image would decode too) is not one of the four.
  dir.write("x/a.png", "GIF89a\x04\x00\x03\x00\x00\x00\x00;");
  expectVolumeLoadError(dir.path("x/a.png"), "not a PNG, JPEG, BMP or binary PGM/PPM image");
  // A PNG signature over a header stb_image cannot read.
  dir.write("x/a.png", std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
  expectVolumeLoadError(dir.path("x/a.png"), "not an image stb_image reads");
  std::string cut = pngBytes(3, 2, 1, 8, slice(0, 1));
  cut.replace(cut.find("IDAT") + 6, 4, "\xff\xff\xff\xff");  // corrupt the deflate stream
  std::filesystem::create_directories(dir.path("y"));
  dir.write("y/a.png", cut);
  expectVolumeLoadError(dir.path("y/a.png"), "cannot decode the image");
  // A header promising more pixels than the file's bytes can hold (stb_image would fill the
  // rest: a 100-byte BMP became a 400 MB volume) is refused before decoding.
  std::filesystem::create_directories(dir.path("z"));
  std::string huge = pngBytes(3, 2, 1, 8, slice(0, 1));
  huge.replace(16, 8, bigEndian32(1u << 14) + bigEndian32(1u << 14));
  dir.write("z/a.png", huge);
  expectVolumeLoadError(dir.path("z"),
                        "its header promises 16384 x 16384 grey 8-bit pixels, more "
                        "than its");
  std::string bmp = "BM" + std::string(52, '\0') + std::string(64, '\x7f');
  const auto put32 = [&](size_t at, uint32_t v) {
    for (int b = 0; b < 4; ++b) bmp[at + b] = char(v >> (8 * b));
  };
  put32(10, 54), put32(14, 40), put32(18, 4000), put32(22, 3000);
  bmp[26] = 1, bmp[28] = 24;  // planes, bits a pixel
  std::filesystem::create_directories(dir.path("w"));
  dir.write("w/b.bmp", bmp);
  expectVolumeLoadError(dir.path("w/b.bmp"), "4000 x 3000 RGB 8-bit pixels, more than its 118");
}

// stb_image asserts on a scan that uses a table no segment defined (Debian 12's libstb: found by
// fuzzing, the input kept in tests/data/fuzz/image): such JPEGs are refused before it decodes.
TEST(ImageStack, JpegScansWithUndefinedTablesAreRefused) {
  TempDir dir;
  std::ifstream in(std::string(EWA_FUZZ_DIR) + "/corpus/image/grey.jpg", std::ios::binary);
  const std::string jpeg((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(jpeg.size(), 160u);
  // Its segments: APP0, DQT, SOF0, DHT DC 0 at byte 102 (22 bytes), DHT AC 0 at 124 (29), SOS.
  ASSERT_EQ(jpeg.substr(124, 2), "\xFF\xC4");
  std::filesystem::create_directories(dir.path("ok"));
  dir.write("ok/a.jpg", jpeg);
  EXPECT_EQ(loadVolume(dir.path("ok")).dims(), (std::array<int64_t, 3>{4, 3, 1}));
  std::filesystem::create_directories(dir.path("ac"));
  dir.write("ac/a.jpg", jpeg.substr(0, 124) + jpeg.substr(124 + 29));
  expectVolumeLoadError(dir.path("ac"),
                        "corrupt JPEG: a scan uses AC Huffman table 0 before any "
                        "defines it");
  std::filesystem::create_directories(dir.path("dc"));
  dir.write("dc/a.jpg", jpeg.substr(0, 102) + jpeg.substr(102 + 22));
  expectVolumeLoadError(dir.path("dc"), "DC Huffman table 0 before any defines it");
  std::filesystem::create_directories(dir.path("q"));
  dir.write("q/a.jpg", jpeg.substr(0, 20) + jpeg.substr(20 + 69));
  expectVolumeLoadError(dir.path("q"), "quantization table 0 before any defines it");
}

}  // namespace
// stb_image grows its buffer to an IDAT chunk's claimed length before reading it (a 358-byte
// file asked for a gigabyte: found by fuzzing, the input kept in tests/data/fuzz/image): a PNG
// whose chunk runs past the file's end is refused before it decodes.
TEST(ImageStack, PngChunksPastTheFilesEndAreRefused) {
  TempDir dir;
  std::ifstream in(std::string(EWA_FUZZ_DIR) + "/corpus/image/grey8.png", std::ios::binary);
  const std::string png((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(png.size(), 33u);
  ASSERT_EQ(png.substr(12, 4), "IHDR");
  std::filesystem::create_directories(dir.path("ok"));
  dir.write("ok/a.png", png);
  EXPECT_EQ(loadVolume(dir.path("ok")).dims()[2], 1);
  // The chunk after IHDR (byte 33) claims 0x40000000 bytes.
  std::string big = png;
  big.replace(33, 4, std::string("\x40\x00\x00\x00", 4));
  std::filesystem::create_directories(dir.path("big"));
  dir.write("big/a.png", big);
  expectVolumeLoadError(dir.path("big"),
                        "corrupt PNG: the chunk at byte 33 claims 1073741824 bytes, past the "
                        "file's end");
  std::ifstream found(
      std::string(EWA_TEST_DIR) + "/data/fuzz/image/oom-png-chunk-length-past-the-end",
      std::ios::binary);
  const std::string kept((std::istreambuf_iterator<char>(found)), {});
  ASSERT_FALSE(kept.empty());
  std::filesystem::create_directories(dir.path("found"));
  dir.write("found/a.png", kept);
  expectVolumeLoadError(dir.path("found"), "corrupt PNG: the chunk at byte");
}

}  // namespace ewa

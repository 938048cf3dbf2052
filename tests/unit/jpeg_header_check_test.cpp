// The JPEG and JPEG 2000 header walks run before GDCM's codecs: well-formed headers pass, and
// each kind of header the codecs abort or crash on is named.
#include "io/jpeg_header_check.h"

#include <gtest/gtest.h>

#include <vector>

namespace ewa {
namespace {

using Bytes = std::vector<uint8_t>;

// A header up to its scan: SOI, JFIF, a frame (SOFn, precision, 16 x 16, `components` of 3
// bytes each) and the start of a scan.
Bytes header(uint8_t sof = 0xC0, int precision = 8, int components = 3, Bytes extra = {}) {
  Bytes b = {0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10, 'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1, 0, 1, 0, 0};
  for (const uint8_t x : extra) b.push_back(x);
  const int length = 8 + 3 * components;
  Bytes frame = {0xFF, sof, 0,  uint8_t(length),    uint8_t(precision), 0,
                 16,   0,   16, uint8_t(components)};
  for (int c = 0; c < components; ++c) frame.insert(frame.end(), {uint8_t(c + 1), 0x11, 0});
  b.insert(b.end(), frame.begin(), frame.end());
  b.insert(b.end(), {0xFF, 0xDA, 0x00, 0x08, 1, 1, 0, 0, 63, 0});
  return b;
}

std::string problem(const Bytes& b) {
  return jpegHeaderProblem(b.data(), b.size());
}

TEST(JpegHeaderCheck, WellFormedHeadersPass) {
  EXPECT_EQ(problem(header()), "");
  EXPECT_EQ(problem(header(0xC0, 8, 1)), "");
  EXPECT_EQ(problem(header(0xC1, 12, 1)), "");  // extended, 12 bits
  EXPECT_EQ(problem(header(0xC2, 8, 3)), "");   // progressive
  for (int p = 8; p <= 16; ++p) EXPECT_EQ(problem(header(0xC3, p, 1)), "") << p;  // lossless
  // Fill bytes before a marker, a comment, a restart interval and an Adobe marker saying YCbCr.
  EXPECT_EQ(problem(header(0xC0, 8, 3, {0xFF, 0xFF, 0xFE, 0,    4,    'h', 'i', 0xFF, 0xDD, 0,
                                        4,    0,    8,    0xFF, 0xEE, 0,   14,  'A',  'd',  'o',
                                        'b',  'e',  0,    100,  0,    0,   0,   0,    1})),
            "");
  // Not the start of a stream (a later fragment of a frame): not walked.
  EXPECT_EQ(problem({0x12, 0x34, 0x56}), "");
  EXPECT_EQ(problem({}), "");
}

TEST(JpegHeaderCheck, HeadersTheCodecAbortsOnAreNamed) {
  // Bytes between markers (found by fuzzing: libjpeg warns, GDCM's codec asserts).
  EXPECT_EQ(problem(header(0xC0, 8, 3, {0x12, 0x34})), "stray bytes between markers");
  // Cut anywhere before the scan.
  const Bytes whole = header();
  for (size_t n = 2; n + 10 < whole.size(); ++n)
    EXPECT_EQ(problem(Bytes(whole.begin(), whole.begin() + long(n))), "cut short") << n;
  Bytes jfif2 = header();
  jfif2[11] = 2;
  EXPECT_EQ(problem(jfif2), "JFIF version 2 (1 only)");
  EXPECT_EQ(problem(header(0xC0, 8, 4)), "4 components (1 or 3)");
  EXPECT_EQ(problem(header(0xC0, 8, 2)), "2 components (1 or 3)");
  EXPECT_EQ(problem(header(0xC9, 8, 3)), "process 0xC9 (arithmetic or hierarchical)");
  EXPECT_EQ(problem(header(0xC5, 8, 3)), "process 0xC5 (arithmetic or hierarchical)");
  // Precisions GDCM's codecs abort or crash on (measured on Debian 12's GDCM 3.0.21).
  for (int p : {0, 1, 2, 7, 17, 20}) EXPECT_NE(problem(header(0xC3, p, 1)), "") << p;
  for (int p : {0, 1, 9, 10, 11, 13, 15, 17}) EXPECT_NE(problem(header(0xC0, p, 1)), "") << p;
  EXPECT_EQ(problem(header(0xC3, 7, 1)), "precision of 7 bits");
  // An Adobe colour transform other than RGB (0) and YCbCr (1) for three components.
  const Bytes adobe2 = {0xFF, 0xEE, 0, 14, 'A', 'd', 'o', 'b', 'e', 0, 100, 0, 0, 0, 0, 2};
  EXPECT_EQ(problem(header(0xC0, 8, 3, adobe2)), "Adobe colour transform 2");
  EXPECT_EQ(problem(header(0xC0, 8, 1, adobe2)), "");  // grey: the transform is not used
  // Impossible structures.
  EXPECT_EQ(problem(header(0xC0, 8, 3, {0xFF, 0xF5, 0, 2})), "unknown marker 0xF5");
  EXPECT_EQ(problem(header(0xC0, 8, 3, {0xFF, 0xFE, 0, 1})), "a marker segment of length 1");
  EXPECT_EQ(problem(header(0xC0, 8, 3, {0xFF, 0xC1, 0, 11, 8, 0, 16, 0, 16, 1, 1, 0x11, 0})),
            "two frame headers");
  EXPECT_EQ(problem({0xFF, 0xD8, 0xFF, 0xDA, 0, 8, 1, 1, 0, 0, 63, 0}),
            "a scan before the frame header");
  EXPECT_EQ(problem({0xFF, 0xD8, 0xFF, 0xD9}), "no image");
  Bytes shortFrame = header(0xC0, 8, 3);
  shortFrame[23] = 8;  // the frame's length leaves no room for its three components
  EXPECT_NE(problem(shortFrame), "");
}

// A JPEG 2000 main header: SOC, SIZ for a `width` x `height` image at (x0, 0) in one tile of
// `tile` pixels, `components` of 8 bits (XRsiz, YRsiz 1), then COD, SOT and SOD (28 bytes).
Bytes codestream(uint32_t width, uint32_t height, int components = 1, uint32_t x0 = 0,
                 uint32_t tile = 64, uint8_t subsampling = 1) {
  Bytes b = {0xFF, 0x4F, 0xFF, 0x51};
  auto u16 = [&](unsigned v) { b.push_back(uint8_t(v >> 8)), b.push_back(uint8_t(v)); };
  auto u32 = [&](uint32_t v) { u16(v >> 16), u16(v & 0xFFFF); };
  u16(38 + 3 * unsigned(components));
  u16(0);  // Rsiz
  u32(x0 + width), u32(height), u32(x0), u32(0), u32(tile), u32(tile), u32(0), u32(0);
  u16(unsigned(components));
  for (int c = 0; c < components; ++c) b.insert(b.end(), {7, subsampling, 1});
  // COD (reversible wavelet), SOT, SOD.
  b.insert(b.end(), {0xFF, 0x52, 0, 12, 0, 0, 0, 1, 0, 1, 4, 4, 0, 1});
  b.insert(b.end(), {0xFF, 0x90, 0, 10, 0, 0, 0, 0, 0, 0, 0, 1, 0xFF, 0x93});
  return b;
}

std::string problem2000(const Bytes& b, int64_t columns, int64_t rows, int64_t samples) {
  return jpeg2000HeaderProblem(b.data(), b.size(), columns, rows, samples);
}

TEST(JpegHeaderCheck, Jpeg2000ImageSizeMustBeTheHeaders) {
  EXPECT_EQ(problem2000(codestream(16, 12), 16, 12, 1), "");
  EXPECT_EQ(problem2000(codestream(16, 12, 3), 16, 12, 3), "");
  EXPECT_EQ(problem2000(codestream(16, 12, 1, 5, 8), 16, 12, 1), "");  // offset, 8-pixel tiles
  // Found by fuzzing: a width of 41 in a 16-column image crashed GDCM with OpenJPEG.
  EXPECT_EQ(problem2000(codestream(41, 16), 16, 16, 1),
            "image of 41 x 16 (the header says 16 x 16)");
  EXPECT_EQ(problem2000(codestream(16, 12, 3), 16, 12, 1), "3 components (SamplesPerPixel 1)");
  EXPECT_EQ(problem2000(codestream(16, 12, 1, 0, 0), 16, 12, 1),
            "tiles that do not cover the image");
  EXPECT_EQ(problem2000(codestream(16, 12, 1, 0, 64, 2), 16, 12, 1), "subsampled components");
  Bytes deep = codestream(16, 12);
  deep[deep.size() - 31] = 16;  // 17-bit samples (the last component, before COD, SOT, SOD)
  EXPECT_EQ(problem2000(deep, 16, 12, 1), "17-bit samples");
  const Bytes whole = codestream(16, 12);
  EXPECT_EQ(problem2000(Bytes(whole.begin(), whole.begin() + 20), 16, 12, 1), "cut short");
  EXPECT_EQ(problem2000({0xFF, 0x4F, 0xFF, 0x52}, 16, 12, 1), "no SIZ marker after SOC");
  // GDCM's own walk skips segments by their lengths (found by fuzzing: an SOT claiming 16896
  // bytes sent it reading past the fragment).
  Bytes longSot = codestream(16, 12);
  longSot[longSot.size() - 12] = 0x42;
  EXPECT_EQ(problem2000(longSot, 16, 12, 1), "a marker segment longer than the stream");
  Bytes shortCod = codestream(16, 12);
  const size_t cod = shortCod.size() - 28;
  ASSERT_EQ(shortCod[cod + 1], 0x52);
  shortCod[cod + 3] = 4;  // COD of 2 bytes, its segment then followed by the rest as markers
  EXPECT_EQ(problem2000(shortCod, 16, 12, 1), "a coding style segment too short");
  // Not a codestream's start (a JP2 box, a later fragment): not walked.
  EXPECT_EQ(problem2000({0, 0, 0, 12, 'j', 'P', ' ', ' '}, 16, 12, 1), "");
}

// A JPEG-LS header: SOI, SOF55 for `width` x `height`, one component of `precision` bits, SOS.
Bytes jpegLs(unsigned width, unsigned height, int precision = 12, int components = 1) {
  Bytes b;
  auto put = [&](std::initializer_list<unsigned> bytes) {
    for (const unsigned x : bytes) b.push_back(uint8_t(x));  // (GCC 12 misjudges insert here)
  };
  put({0xFF, 0xD8, 0xFF, 0xF7, 0, 8 + 3 * unsigned(components), unsigned(precision), height >> 8,
       height & 255, width >> 8, width & 255, unsigned(components)});
  for (int c = 0; c < components; ++c) put({unsigned(c + 1), 0x11, 0});
  put({0xFF, 0xDA, 0, 8, 1, 1, 0, 0, 0, 0});
  return b;
}

std::string problemLs(const Bytes& b, int64_t columns, int64_t rows, int64_t samples,
                      int64_t bits) {
  return jpegLsHeaderProblem(b.data(), b.size(), columns, rows, samples, bits);
}

TEST(JpegHeaderCheck, JpegLsFrameMustBeTheHeaders) {
  EXPECT_EQ(problemLs(jpegLs(16, 12), 16, 12, 1, 16), "");
  EXPECT_EQ(problemLs(jpegLs(16, 12, 8, 3), 16, 12, 3, 8), "");
  // Found by fuzzing: a frame smaller than Rows x Columns made GDCM assert on its buffer.
  EXPECT_EQ(problemLs(jpegLs(8, 8), 8, 65528, 1, 16), "image of 8 x 8 (the header says 8 x 65528)");
  EXPECT_EQ(problemLs(jpegLs(16, 12, 8, 3), 16, 12, 1, 8), "3 components (SamplesPerPixel 1)");
  EXPECT_EQ(problemLs(jpegLs(16, 12, 12), 16, 12, 1, 8), "precision of 12 bits (BitsAllocated 8)");
  EXPECT_EQ(problemLs(jpegLs(16, 12, 1), 16, 12, 1, 8), "precision of 1 bits (BitsAllocated 8)");
  const Bytes whole = jpegLs(16, 12);
  EXPECT_EQ(problemLs(Bytes(whole.begin(), whole.begin() + 8), 16, 12, 1, 16), "cut short");
  EXPECT_EQ(problemLs({0xFF, 0xD8, 0xFF, 0xDA, 0, 8, 1, 1, 0, 0, 0, 0}, 16, 12, 1, 16),
            "a scan before the frame header");
  EXPECT_EQ(problemLs({1, 2, 3}, 16, 12, 1, 16), "");  // not a stream's start
  EXPECT_TRUE(isJpegLsTransferSyntax("1.2.840.10008.1.2.4.80"));
  EXPECT_FALSE(isJpegLsTransferSyntax("1.2.840.10008.1.2.4.50"));
}

TEST(JpegHeaderCheck, OnlyJpegTransferSyntaxesAreWalked) {
  for (const char* uid : {"1.2.840.10008.1.2.4.50", "1.2.840.10008.1.2.4.51",
                          "1.2.840.10008.1.2.4.57", "1.2.840.10008.1.2.4.70"})
    EXPECT_TRUE(isJpegTransferSyntax(uid)) << uid;
  for (const char* uid :
       {"1.2.840.10008.1.2.4.80", "1.2.840.10008.1.2.4.90", "1.2.840.10008.1.2.1",
        "1.2.840.10008.1.2.5", "1.2.840.10008.1.2.4.5", "1.2.840.10008.1.2.4.500", ""})
    EXPECT_FALSE(isJpegTransferSyntax(uid)) << uid;
}

}  // namespace
}  // namespace ewa

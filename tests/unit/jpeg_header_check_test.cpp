// The JPEG header walk run before GDCM's JPEG codec: well-formed headers pass, and each kind of
// header the codec aborts or crashes on is named.
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
  b.insert(b.end(), extra.begin(), extra.end());
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

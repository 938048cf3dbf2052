// The one helper image tests use: compare a rendered image with a reference PNG in tests/.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "io/png_io.h"

namespace ewa::test {

// The background an image was drawn over, as 8-bit RGB (what `--background R,G,B` gives).
using Rgb8 = std::array<uint8_t, 3>;
Rgb8 backgroundRgb8(double r, double g, double b);

// How two pictures differ, in RGB only (alpha is ignored: it is 255 everywhere in a PNG from
// ewaview and would only dilute the mean), over the pixels the object covers: those where
// either picture differs from the background by more than 2 levels in a channel.
struct ImageDifference {
  double mean = 0.0;         // mean absolute channel difference over covered pixels, 0..255
  double badFraction = 0.0;  // covered pixels off by more than the pixel tolerance in a channel
  size_t covered = 0;        // number of covered pixels
};
ImageDifference compareCovered(const Image8& a, const Image8& b, const Rgb8& background,
                               int pixelTolerance);

// The largest absolute difference of one channel between two pictures of one size, 0..255
// (255, and a failed expectation, when their sizes differ).
int maxDifference(const Image8& a, const Image8& b);
// Levels two frames of one setting may differ by when the GPU's slab partition drew them: its
// order of a slab's entries varies between frames, and half-float sums round apart with it (up
// to 3 on an H200); the CPU's partition draws them equal to the bit.
constexpr int kGpuPartitionLevels = 3;
// Mean of all channels of all pixels (0 for an empty image).
double meanValue(const Image8& a);

// Reads tests/reference/<name>.png; throws std::runtime_error when absent or unreadable.
Image8 readReference(const std::string& name);

// Compares `actual` with tests/reference/<name>.png through compareCovered. Passes when the
// mean is at most `meanTolerance` and no more than `maxBadFraction` of the covered pixels differ
// by more than `pixelTolerance` (0..255 units); fails when nothing is covered. On failure writes
// <name>.actual.png and <name>.diff.png into the test output folder and says where.
// With EWA_UPDATE_REFERENCES=1 in the environment it (re)writes the reference instead.
::testing::AssertionResult matchesReference(const std::string& name, const Image8& actual,
                                            const Rgb8& background, double meanTolerance,
                                            int pixelTolerance, double maxBadFraction);

// Folder where tests write their output images; created on demand.
std::string testOutputDir();

}  // namespace ewa::test

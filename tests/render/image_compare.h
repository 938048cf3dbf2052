// The one helper image tests use: compare a rendered image with a reference PNG in tests/.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "io/png_io.h"

namespace ewa::test {

// Compares `actual` with tests/reference/<name>.png. Passes when the mean absolute channel
// difference is at most `meanTolerance` and no more than `maxBadFraction` of the pixels
// differ by more than `pixelTolerance` in any channel (0..255 units). On failure writes
// <name>.actual.png and <name>.diff.png into the test output folder and says where.
// With EWA_UPDATE_REFERENCES=1 in the environment it (re)writes the reference instead.
::testing::AssertionResult matchesReference(const std::string& name, const Image8& actual,
                                            double meanTolerance, int pixelTolerance,
                                            double maxBadFraction);

// Folder where tests write their output images; created on demand.
std::string testOutputDir();

}  // namespace ewa::test

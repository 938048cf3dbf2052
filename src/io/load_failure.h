// Helpers that build the one-line "<path>: <problem>" LoadError every loader throws.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/volume_loader.h"

namespace ewa {

// Replaces line breaks and other control characters by spaces: messages may quote file text.
std::string oneLine(std::string_view text);
// Quotes file text for a message, cut to `maxChars` so a garbage header cannot flood the line.
std::string quoteText(std::string_view text, size_t maxChars = 60);
// Throws LoadError("<path>: <problem>").
[[noreturn]] void failLoad(const std::string& path, const std::string& problem);
// Throws "<path>: --channel C is out of range (N channels)" unless 0 <= channel < channels: the
// one check of --channel for every multi-channel format (TIFF, RGB DICOM).
void checkChannel(const std::string& path, int64_t channel, int64_t channels);
// Throws "<path>: --frame F is out of range (<holder> N <noun>s<after>)" unless
// 0 <= frame < frames: the one check of --frame for every format of several volumes (4D NIfTI
// and NRRD, TIFF time points, a DICOM series' volumes).
void checkFrame(const std::string& path, int64_t frame, int64_t frames,
                const std::string& holder = "the file has", const std::string& noun = "frame",
                const std::string& after = "");

}  // namespace ewa

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

}  // namespace ewa

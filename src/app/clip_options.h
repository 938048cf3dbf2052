// The command-line options of the crop box and clipping planes (--crop, --clip-plane).
#pragma once

#include <string>
#include <vector>

#include "core/clip_region.h"

namespace CLI {
class App;
}

namespace ewa {

struct ClipOptionText {
  std::string crop;
  std::vector<std::string> planes;
};

// Adds --crop and the repeatable --clip-plane to `app`, writing into `text`.
void addClipOptions(CLI::App& app, ClipOptionText& text);
// Turns the parsed text into `region`; returns a usage error message, or "" when all is well.
std::string finishClipOptions(const ClipOptionText& text, ClipRegion* region);

}  // namespace ewa

// The command-line options of the crop box and clipping planes (CLI11).
#include "app/clip_options.h"

#include <CLI/CLI.hpp>

#include "app/option_binding.h"

namespace ewa {

void addClipOptions(CLI::App& app, ClipOptionText& text) {
  addTableOption(app, "--crop", text.crop);
  addTableOption(app, "--clip-plane", text.planes)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::string finishClipOptions(const ClipOptionText& text, ClipRegion* region) {
  if (!text.crop.empty())
    if (std::string e = parseCropBox(text.crop, region); !e.empty()) return e;
  if (text.planes.size() > ClipRegion::kMaxPlanes)
    return "--clip-plane: at most " + std::to_string(ClipRegion::kMaxPlanes) + " planes, got " +
           std::to_string(text.planes.size());
  for (const std::string& plane : text.planes)
    if (std::string e = parseClipPlane(plane, region); !e.empty()) return e;
  return "";
}

}  // namespace ewa

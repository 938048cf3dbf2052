// The command-line options of the crop box and clipping planes (CLI11).
#include "app/clip_options.h"

#include <CLI/CLI.hpp>

namespace ewa {

void addClipOptions(CLI::App& app, ClipOptionText& text) {
  app.add_option("--crop", text.crop,
                 "Keep only the world-space box X0,X1,Y0,Y1,Z0,Z1 (every renderer and mode)");
  app.add_option("--clip-plane", text.planes,
                 "Keep the half-space in front of the plane through PX,PY,PZ with normal "
                 "NX,NY,NZ (repeat for up to 6 planes; --clip-plane=-1,... for a leading minus)")
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

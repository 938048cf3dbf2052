// Import of ParaView colour-map presets (JSON with "RGBPoints" and optional opacity "Points").
#pragma once

#include <string>
#include <vector>

#include "core/transfer_function.h"

namespace ewa {

struct ImportedColorMap {
  std::string name;               // "Name", or "preset N" when it has none
  std::vector<ColorPoint> color;  // from "RGBPoints": x, r, g, b, ...
  std::vector<OpacityPoint>
      opacity;  // from "Points": x, alpha, midpoint, sharpness, ... (may be empty)
};

// Parses the text of a ParaView preset file: one preset object or an array of them. Presets
// without "RGBPoints" inside an array (e.g. categorical "IndexedColors" maps) are skipped.
// Midpoint and sharpness are read but not used (the editor's curves are piecewise linear).
// Throws std::runtime_error("<nameForErrors>: <problem>") for invalid JSON, a wrong shape,
// numbers out of range, or no usable preset.
std::vector<ImportedColorMap> parseParaViewPresets(const std::string& text,
                                                   const std::string& nameForErrors);

// Reads and parses `path`. Throws std::runtime_error("<path>: <problem>").
std::vector<ImportedColorMap> loadParaViewPresets(const std::string& path);

// `current` with the map's colours, and its opacity when it has some. With `rescale`, the map's
// own value range (of its colour points) is stretched onto [lo, hi] as ParaView does when it
// applies a preset; otherwise its values are used as they are.
TransferFunction applyImportedColorMap(const TransferFunction& current, const ImportedColorMap& map,
                                       double lo, double hi, bool rescale);

// A JSON file dropped on the window: ewaview's transfer function, else a ParaView preset file
// (its first preset applied to `current`, rescaled onto [lo, hi]). `*what` says which
// ("loaded PATH", "imported "NAME" from PATH"). Throws std::runtime_error("path: problem") with
// the transfer-function reader's problem when neither reads it.
TransferFunction loadTransferFunctionOrPreset(const std::string& path,
                                              const TransferFunction& current, double lo, double hi,
                                              std::string* what);

}  // namespace ewa

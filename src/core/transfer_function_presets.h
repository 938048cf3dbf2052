// Transfer-function presets (CT bone, CT soft tissue, MR, grayscale, colour maps) scaled to a
// volume.
#pragma once

#include <string>
#include <vector>

#include "core/transfer_function.h"

namespace ewa {

struct TransferFunctionPresetInfo {
  std::string name;  // as the editor's menu shows it: "CT bone", "Viridis (colour map)"
  bool colorOnly;    // a colour map: replaces the colours and keeps the opacity
  std::string key;   // as --tf-preset names it: "ct-bone", "viridis"
};

// Every preset, in menu order: the full presets first, then the colour maps.
const std::vector<TransferFunctionPresetInfo>& transferFunctionPresets();

// `current` with preset `name` (its name or its key) applied for values in [lo, hi]. Full presets
// replace both point lists; colour maps replace the colours only. The opacity unit distance is
// kept. CT presets are written in Hounsfield units: used as they are when [lo, hi] looks like HU
// (lo <= -500 and hi >= 500), otherwise [-1000, 2000] HU is mapped onto [lo, hi]. The others are
// placed at fractions of [lo, hi]. Throws std::invalid_argument for an unknown name or a bad range.
TransferFunction applyTransferFunctionPreset(const TransferFunction& current,
                                             const std::string& name, double lo, double hi);

}  // namespace ewa

// Front-to-back compositing of sheared slices (or pre-integrated slabs) into the intermediate
// image.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "core/intermediate_image.h"
#include "core/shear_warp_clip.h"
#include "core/shear_warp_factorization.h"
#include "core/shear_warp_settings.h"
#include "core/shear_warp_volume.h"

namespace ewa {

// One buffered back-slice sample: its table coordinate and the slice it belongs to (a cell
// that a skipped slab did not fill holds an older slice's tag and is recomputed).
struct BufferedSample {
  float value = 0.0f;
  int32_t slice = -1;
};

// Buffers kept between frames so that they are allocated only when they grow.
struct CompositorBuffers {
  std::vector<BufferedSample> image;                // intermediate-image-sized (IB)
  std::vector<std::vector<BufferedSample>> slices;  // two slice-sized (SB) per thread
  std::vector<int32_t> links;                       // opaque-pixel links, one array per row
  std::vector<float> rayRatios;  // perspective: each intermediate pixel's d'/d (rayRatio)
};

struct CompositeInput {
  const ShearWarpFactorization* view = nullptr;
  const float* slices = nullptr;          // ShearWarpVolume::slices(view->principal)
  const CellRuns* runs = nullptr;         // undilated (standard) or dilated (pre-integrated)
  const glm::vec4* pointTable = nullptr;  // standard: tableSize entries, corrected for the view
  const glm::vec4* pairTable = nullptr;   // pre-integrated: (2 tableSize - 1) x tableSize,
                                          // diagonal-major (see lookupPair), corrected
  // ln(1 - alpha) of each entry of the table in use: perspective views correct by it (none:
  // uncorrected).
  const float* tableLog = nullptr;
  int tableSize = 256;
  ShearWarpSettings settings;
  const ShearWarpClip* clip = nullptr;  // crop box and planes; null or inactive: none
  int32_t* links = nullptr;             // set by compositeSlices
  const float* rayRatios = nullptr;     // set by compositeSlices for perspective correction
};

// Composites every slice (standard: bilinear sample in the slice, nearest point-table entry) or
// every slab between adjacent slices (pre-integrated: front and back samples, pair-table
// lookup) front to back into `out`, which is reset to the view's intermediate size (perspective
// and magnified views: compositePerspective, shear_warp_perspective.h). Intermediate
// rows are shared out among `threads` threads (row v to thread v mod threads).
void compositeSlices(const CompositeInput& input, int threads, CompositorBuffers& buffers,
                     IntermediateImage& out);

}  // namespace ewa

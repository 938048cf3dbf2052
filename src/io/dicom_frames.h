// The frames of one multi-frame (enhanced) DICOM file as slices: each frame's plane position,
// orientation and pixel spacing from the functional group sequences.
#pragma once

#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// `file`, a multi-frame image, as one slice a frame (DicomSlice::frame its frame, in stored
// order) with the geometry its Shared and Per-frame Functional Groups give (Plane Position,
// Plane Orientation, Pixel Measures; a per-frame value over the shared one). Empty when the
// file has no per-frame positions for all of its frames (a multi-frame file of another kind:
// the caller keeps it whole). Throws LoadError for functional groups it cannot read.
std::vector<DicomSlice> dicomFrameSlices(const DicomSlice& file);

}  // namespace ewa

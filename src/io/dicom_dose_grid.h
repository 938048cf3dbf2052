// RT Dose grids: the frames of a multi-frame RT Dose file as slices placed by their offsets.
#pragma once

#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

inline constexpr const char* kRtDoseStorageUid = "1.2.840.10008.5.1.4.1.1.481.2";

// Why GDCM's image reader would abort on an RT Dose file (SOP class kRtDoseStorageUid) whose
// GridFrameOffsetVector (3004,000C) is `offsets` ("" when absent) and which has (0028,0008)
// NumberOfFrames or not (`hasFrameCount`); "" when it would not. GDCM takes the z spacing from
// the first two offsets, sized by the frame count, and asserts when that element is missing or
// fewer than two offsets parse as numbers (a one-frame grid among them).
std::string doseGridHeaderProblem(const std::string& offsets, bool hasFrameCount);

// Whether `file` is an RT Dose (SOP class 1.2.840.10008.5.1.4.1.1.481.2 or modality RTDOSE)
// multi-frame file with a GridFrameOffsetVector (3004,000C) of one offset a frame, an
// ImagePositionPatient and an ImageOrientationPatient: then its frames as slices (frame k at the
// position plus offset k minus offset 0 along the normal, in stored order: whether the offsets
// are relative, starting at 0, or the frames' z, they differ by the same steps), else empty. No
// other code gives the dose grid its z spacing, which would otherwise be assumed 1.
std::vector<DicomSlice> doseGridFrameSlices(const DicomSlice& file);

}  // namespace ewa

// One DICOM file's pixels through GDCM: checked, decoded and rescaled; the volume type that
// holds a series' values.
#pragma once

#include <gdcmPixelFormat.h>

#include <cstdint>
#include <vector>

#include "io/dicom_series.h"
#include "io/volume_layout.h"

namespace ewa {

// One slice's pixels decoded (any transfer syntax GDCM decodes) as doubles after rescale.
struct SlicePixels {
  std::vector<double> values;
  double slope = 1.0, intercept = 0.0;
  gdcm::PixelFormat::ScalarType type = gdcm::PixelFormat::UNKNOWN;
};

// Every frame of `slice`'s file, in stored order; of an RGB image, channel `channel` (0 red, 1
// green, 2 blue). Throws LoadError naming the file for pixel modules GDCM would assert on, sizes
// the data cannot hold, data it cannot decode and a channel the image does not have.
SlicePixels readSlice(const DicomSlice& slice, int channel = 0);
// The narrowest volume type that holds every value exactly (`integral`: all are integers).
FileScalar fittingType(const std::vector<double>& values, bool integral);

}  // namespace ewa

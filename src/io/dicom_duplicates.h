// Copies of one DICOM image in a folder (a study exported twice, "IM1 (copy)"): kept once.
#pragma once

#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// Drops from each series the files that hold an image already in it: the same
// SOPInstanceUID, position and InstanceNumber (a UID alone is not enough: some anonymizers give
// every image one). The file the user named is kept, else the first by path. Each dropped file
// is added to `skipped` as "FILE: the same image as KEPT (SOPInstanceUID UID)".
void dropDuplicateImages(std::vector<DicomSeries>& all, std::vector<std::string>& skipped);

}  // namespace ewa

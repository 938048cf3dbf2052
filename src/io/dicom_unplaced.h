// DICOM slices without ImagePositionPatient (ACR-NEMA files, secondary captures): placed in order.
#pragma once

#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// What placeUnplacedSlices assumed.
struct UnplacedSlices {
  bool orientationAssumed = false;  // no slice had an orientation: rows along x, columns along y
};

// Places the slices of a series none of which has an ImagePositionPatient, as old ACR-NEMA
// files and secondary captures come: by SliceLocation when every slice has a different one,
// else in InstanceNumber order (then file name), SpacingBetweenSlices, SliceThickness or 1
// apart (the first slice's), along the normal of their orientation (rows along x, columns along
// y when no slice has one). Gives each slice the position that says so, for sortDicomSlices,
// and adds a note saying how they were placed. Leaves the slices alone when any has a position
// or there are fewer than two.
UnplacedSlices placeUnplacedSlices(std::vector<DicomSlice>& slices,
                                   std::vector<std::string>& notes);

}  // namespace ewa

// DICOM slices without ImagePositionPatient (ACR-NEMA files, secondary captures): placed in order.
#pragma once

#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// What placeUnplacedSlices assumed.
struct UnplacedSlices {
  bool orientationAssumed = false;  // no slice had an orientation: rows along x, columns along y
  bool equipmentAxes = false;       // placed by ACR-NEMA's retired Image Position: not patient axes
};

// Places the slices of a series none of which has an ImagePositionPatient, as old ACR-NEMA
// files and secondary captures come: by ACR-NEMA's retired Image Position (and Orientation)
// when every slice has a different one on a line along the slices' normal (in the equipment's
// axes, not the patient's), else by SliceLocation when every slice has a different one,
// else in InstanceNumber order (then file name), SpacingBetweenSlices, SliceThickness or 1
// apart (the first slice's), along the normal of their orientation (rows along x, columns along
// y when no slice has one). Gives each slice the position that says so, for sortDicomSlices,
// and adds a note saying how they were placed. Leaves the slices alone when any has a position
// or there are fewer than two.
UnplacedSlices placeUnplacedSlices(std::vector<DicomSlice>& slices,
                                   std::vector<std::string>& notes);

}  // namespace ewa

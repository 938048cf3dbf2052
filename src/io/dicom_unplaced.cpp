// placeUnplacedSlices: slice order and spacing from SliceLocation or InstanceNumber.
#include "io/dicom_unplaced.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "io/text_numbers.h"

namespace ewa {

namespace {

constexpr double kSameLocation = 1e-4;  // mm: locations written as equal text

// Whether every slice has a SliceLocation and no two share one.
bool distinctLocations(const std::vector<DicomSlice>& slices) {
  std::vector<double> at;
  for (const DicomSlice& s : slices) {
    if (!s.hasSliceLocation) return false;
    at.push_back(s.sliceLocation);
  }
  std::sort(at.begin(), at.end());
  for (size_t i = 1; i < at.size(); ++i)
    if (at[i] - at[i - 1] < kSameLocation) return false;
  return true;
}

}  // namespace

UnplacedSlices placeUnplacedSlices(std::vector<DicomSlice>& slices,
                                   std::vector<std::string>& notes) {
  UnplacedSlices result;
  if (slices.size() < 2) return result;
  for (const DicomSlice& s : slices)
    if (s.hasPosition) return result;
  result.orientationAssumed = std::none_of(slices.begin(), slices.end(),
                                           [](const DicomSlice& s) { return s.hasOrientation; });
  if (result.orientationAssumed) {
    for (DicomSlice& s : slices) s.hasOrientation = true;  // the default: rows x, columns y
    notes.push_back("no ImageOrientationPatient: rows along x and columns along y assumed");
  }
  const auto& o = slices.front().orientation;
  glm::dvec3 normal = glm::cross(glm::dvec3(o[0], o[1], o[2]), glm::dvec3(o[3], o[4], o[5]));
  // A degenerate orientation is sortDicomSlices' error; the slices still get distinct places.
  normal = glm::length(normal) > 1e-6 ? glm::normalize(normal) : glm::dvec3(0, 0, 1);
  if (distinctLocations(slices)) {
    for (DicomSlice& s : slices) s.position = normal * s.sliceLocation + 0.0, s.hasPosition = true;
    notes.push_back("no ImagePositionPatient: slices placed by their SliceLocation");
    return result;
  }
  std::stable_sort(slices.begin(), slices.end(), [](const DicomSlice& a, const DicomSlice& b) {
    return a.instance != b.instance ? a.instance < b.instance : a.file < b.file;
  });
  const DicomSlice& first = slices.front();
  double step = 1.0;
  const char* from = " (assumed)";
  if (first.spacingBetweenSlices > 0.0)
    step = first.spacingBetweenSlices, from = " (SpacingBetweenSlices)";
  else if (first.sliceThickness > 0.0)
    step = first.sliceThickness, from = " (SliceThickness)";
  for (size_t i = 0; i < slices.size(); ++i)
    slices[i].position = normal * (double(i) * step), slices[i].hasPosition = true;
  notes.push_back(
      "no ImagePositionPatient or distinct SliceLocation: slices stacked in "
      "InstanceNumber order, " +
      shortText(step) + " apart" + from);
  return result;
}

}  // namespace ewa

// placeUnplacedSlices: slice order and spacing from ACR-NEMA positions, SliceLocation or
// InstanceNumber.
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

// Places the slices by ACR-NEMA's retired Image Position when every slice has one, no two
// share one and they lie on one line along the normal (of ImageOrientationPatient, else the
// retired Image Orientation when every slice has one, else rows x and columns y): a position
// off that line may be in another convention than the orientation's, which SliceLocation or
// InstanceNumber order place more safely. Returns whether it placed them.
bool placeByRetiredPosition(std::vector<DicomSlice>& slices, std::vector<std::string>& notes) {
  const auto all = [&](bool DicomSlice::*flag) {
    return std::all_of(slices.begin(), slices.end(), [&](const DicomSlice& s) { return s.*flag; });
  };
  const auto none = [&](bool DicomSlice::*flag) {
    return std::none_of(slices.begin(), slices.end(), [&](const DicomSlice& s) { return s.*flag; });
  };
  if (!all(&DicomSlice::hasRetiredPosition)) return false;
  const bool retiredOrientation =
      none(&DicomSlice::hasOrientation) && all(&DicomSlice::hasRetiredOrientation);
  const bool assumed = none(&DicomSlice::hasOrientation) && !retiredOrientation;
  const DicomSlice& first = slices.front();
  const glm::dvec3 normal =
      dicomSliceNormal(retiredOrientation ? first.retiredOrientation : first.orientation);
  std::vector<double> along;
  const glm::dvec3 p0 = first.retiredPosition;
  for (const DicomSlice& s : slices) {
    const glm::dvec3 d = s.retiredPosition - p0;
    const double t = glm::dot(d, normal);
    const double tolerance = 1e-3 + 1e-4 * glm::length(s.retiredPosition);
    if (glm::length(d - t * normal) > tolerance) return false;
    along.push_back(t);
  }
  std::sort(along.begin(), along.end());
  for (size_t i = 1; i < along.size(); ++i)
    if (along[i] - along[i - 1] < kSameLocation) return false;
  for (DicomSlice& s : slices) {
    s.position = s.retiredPosition, s.hasPosition = true;
    if (retiredOrientation) s.orientation = s.retiredOrientation;
    if (retiredOrientation || assumed) s.hasOrientation = true;  // assumed: rows x, columns y
  }
  if (assumed)
    notes.push_back("no ImageOrientationPatient: rows along x and columns along y assumed");
  notes.push_back(std::string("no ImagePositionPatient: slices placed by ACR-NEMA's Image Position "
                              "(0020,0030)") +
                  (retiredOrientation ? " and Image Orientation (0020,0035)" : "") +
                  ", in the equipment's axes, not the patient's");
  return true;
}

}  // namespace

UnplacedSlices placeUnplacedSlices(std::vector<DicomSlice>& slices,
                                   std::vector<std::string>& notes) {
  UnplacedSlices result;
  if (slices.size() < 2) return result;
  for (const DicomSlice& s : slices)
    if (s.hasPosition) return result;
  if (placeByRetiredPosition(slices, notes)) {
    result.equipmentAxes = true;
    return result;
  }
  result.orientationAssumed = std::none_of(slices.begin(), slices.end(),
                                           [](const DicomSlice& s) { return s.hasOrientation; });
  if (result.orientationAssumed) {
    for (DicomSlice& s : slices) s.hasOrientation = true;  // the default: rows x, columns y
    notes.push_back("no ImageOrientationPatient: rows along x and columns along y assumed");
  }
  const glm::dvec3 normal = dicomSliceNormal(slices.front().orientation);
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

// DICOM series holding several volumes at the same positions: grouped by position, one picked.
#include "io/dicom_volumes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "io/load_failure.h"

namespace ewa {

namespace {

constexpr double kSamePosition = 1e-4;  // mm along the normal: repeated positions are equal text

// --frame against the series' volumes (1 when it holds one).
void checkVolume(const std::string& path, int volume, size_t count) {
  checkFrame(path, volume, int64_t(count), "the series has", "volume", " at its positions");
}

}  // namespace

std::vector<DicomSlice> selectDicomVolume(const std::string& path, std::vector<DicomSlice> slices,
                                          int volume, std::vector<std::string>& notes, int* count) {
  if (count) *count = 1;
  const bool placed =
      slices.size() > 1 && std::all_of(slices.begin(), slices.end(), [&](const DicomSlice& s) {
        return s.hasPosition && s.hasOrientation && sameDicomOrientation(s, slices.front());
      });
  if (!placed) {
    checkVolume(path, volume, 1);
    return slices;
  }
  const auto& o = slices.front().orientation;
  const glm::dvec3 normal = glm::cross(glm::dvec3(o[0], o[1], o[2]), glm::dvec3(o[3], o[4], o[5]));
  auto along = [&](const DicomSlice& s) { return glm::dot(s.position, normal); };
  // By position, and at each position by InstanceNumber, frame and file: the volumes' order.
  std::stable_sort(slices.begin(), slices.end(), [&](const DicomSlice& a, const DicomSlice& b) {
    const double da = along(a), db = along(b);
    if (std::fabs(da - db) > kSamePosition) return da < db;
    if (a.instance != b.instance) return a.instance < b.instance;
    if (a.frame != b.frame) return a.frame < b.frame;
    return a.file < b.file;
  });
  std::vector<size_t> starts{0};  // where each position's run begins
  for (size_t i = 1; i < slices.size(); ++i)
    if (std::fabs(along(slices[i]) - along(slices[i - 1])) > kSamePosition) starts.push_back(i);
  const size_t positions = starts.size();
  starts.push_back(slices.size());
  size_t fewest = slices.size(), most = 0;
  for (size_t p = 0; p < positions; ++p) {
    fewest = std::min(fewest, starts[p + 1] - starts[p]);
    most = std::max(most, starts[p + 1] - starts[p]);
  }
  if (positions < 2 || most == 1) {  // one place (a cine), or one volume
    checkVolume(path, volume, 1);
    return slices;
  }
  if (fewest != most) {
    size_t p = 0;  // a position holding the most, whose files are named
    while (starts[p + 1] - starts[p] != most) ++p;
    failLoad(path, std::to_string(positions) + " slice positions holding " +
                       std::to_string(fewest) + " to " + std::to_string(most) + " slices each (" +
                       slices[starts[p]].file + " and " + slices[starts[p] + 1].file +
                       " share one position): several volumes in the series, unevenly (a copy? "
                       "a missing file?)");
  }
  checkVolume(path, volume, most);
  if (count) *count = int(most);
  std::vector<DicomSlice> picked;
  for (size_t p = 0; p < positions; ++p) picked.push_back(slices[starts[p] + size_t(volume)]);
  notes.push_back(std::to_string(most) + " volumes at the same " + std::to_string(positions) +
                  " positions (diffusion directions, echoes or time points): volume " +
                  std::to_string(volume) + " open (--frame N opens another, 0 to " +
                  std::to_string(most - 1) + ")");
  return picked;
}

std::optional<glm::dvec3> stackOnePosition(std::vector<DicomSlice>& slices,
                                           std::vector<std::string>& notes) {
  if (slices.size() < 2) return std::nullopt;
  for (const DicomSlice& s : slices)
    if (!s.hasPosition || !s.hasOrientation || s.frames != 1 ||
        !sameDicomOrientation(s, slices.front()) ||
        glm::length(s.position - slices.front().position) > kSamePosition)
      return std::nullopt;
  std::stable_sort(slices.begin(), slices.end(), [](const DicomSlice& a, const DicomSlice& b) {
    return a.instance != b.instance ? a.instance < b.instance : a.file < b.file;
  });
  notes.push_back(std::to_string(slices.size()) +
                  " images at one position (a cine or a time series): stacked in "
                  "InstanceNumber order, 1 apart");
  return dicomSliceNormal(slices.front().orientation);
}

}  // namespace ewa

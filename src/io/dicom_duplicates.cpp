// dropDuplicateImages: one slice per image when a folder holds copies of its files.
#include "io/dicom_duplicates.h"

#include <glm/geometric.hpp>
#include <map>
#include <utility>

namespace ewa {

namespace {

constexpr double kSamePosition = 1e-4;  // mm: copies carry the same text

bool sameImage(const DicomSlice& a, const DicomSlice& b) {
  return a.instance == b.instance && a.hasPosition == b.hasPosition &&
         glm::length(a.position - b.position) <= kSamePosition;
}

}  // namespace

void dropDuplicateImages(std::vector<DicomSeries>& all, std::vector<std::string>& skipped) {
  for (DicomSeries& series : all) {
    std::map<std::string, std::vector<size_t>> byUid;  // kept slices with each UID
    std::vector<DicomSlice> kept;
    for (DicomSlice& s : series.slices) {
      if (s.sopInstanceUid.empty()) {
        kept.push_back(std::move(s));
        continue;
      }
      std::vector<size_t>& same = byUid[s.sopInstanceUid];
      size_t match = 0;
      while (match < same.size() && !sameImage(kept[same[match]], s)) ++match;
      if (match == same.size()) {
        same.push_back(kept.size());
        kept.push_back(std::move(s));
        continue;
      }
      DicomSlice& first = kept[same[match]];
      if (s.named) std::swap(first, s);  // the named file stays
      skipped.push_back(s.file + ": the same image as " + first.file + " (SOPInstanceUID " +
                        s.sopInstanceUid + ")");
    }
    series.slices = std::move(kept);
  }
}

}  // namespace ewa

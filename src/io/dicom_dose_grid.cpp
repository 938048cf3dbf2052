// doseGridFrameSlices: an RT Dose file's frames placed by GridFrameOffsetVector (3004,000C).
#include "io/dicom_dose_grid.h"

#include <gdcmReader.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

const gdcm::Tag kSopClass(0x0008, 0x0016);
const gdcm::Tag kModality(0x0008, 0x0060);
const gdcm::Tag kGridFrameOffsets(0x3004, 0x000c);
const gdcm::Tag kPixelData(0x7fe0, 0x0010);

// The text of element `tag` of `ds` up to `maxBytes` long, trimmed of padding; empty when
// absent or longer.
std::string elementText(const gdcm::DataSet& ds, const gdcm::Tag& tag, size_t maxBytes = 256) {
  if (!ds.FindDataElement(tag)) return {};
  const gdcm::ByteValue* value = ds.GetDataElement(tag).GetByteValue();
  if (!value || value->GetLength() > maxBytes) return {};
  std::string text(value->GetPointer(), value->GetLength());
  while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
  return trim(text);
}

}  // namespace

std::string doseGridHeaderProblem(const std::string& offsets, bool hasFrameCount) {
  std::string text = offsets;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
  if (text.empty()) return {};  // GDCM leaves the spacing alone
  if (!hasFrameCount)
    return "an RT Dose GridFrameOffsetVector (3004,000C) without NumberOfFrames (0028,0008), "
           "which GDCM's reader aborts on";
  // Stricter than GDCM (every offset a number), so that nothing it would stop on gets past.
  if (dicomNumbers(text.c_str()).size() < 2)
    return "an RT Dose GridFrameOffsetVector (3004,000C) of fewer than two numbers (" +
           quoteText(text, 40) + "), which GDCM's reader aborts on";
  return {};
}

std::vector<DicomSlice> doseGridFrameSlices(const DicomSlice& file) {
  if (file.frames < 2 || !file.hasPosition || !file.hasOrientation) return {};
  gdcm::Reader reader;
  reader.SetFileName(file.file.c_str());
  if (!reader.ReadUpToTag(kPixelData)) failLoad(file.file, "GDCM cannot read the header");
  const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
  if (elementText(ds, kSopClass) != kRtDoseStorageUid && elementText(ds, kModality) != "RTDOSE")
    return {};
  // Up to 32 characters an offset (a DS value has at most 16, and its backslash).
  const std::vector<double> offsets = dicomNumbers(
      elementText(ds, kGridFrameOffsets, size_t(std::min<int64_t>(file.frames, 1 << 20)) * 32)
          .c_str());
  if (int64_t(offsets.size()) != file.frames) return {};
  const glm::dvec3 normal = dicomSliceNormal(file.orientation);
  std::vector<DicomSlice> frames;
  for (size_t f = 0; f < offsets.size(); ++f) {
    DicomSlice s = file;
    s.frames = 1;
    s.frame = int64_t(f);
    s.position = file.position + (offsets[f] - offsets.front()) * normal;
    frames.push_back(s);
  }
  return frames;
}

}  // namespace ewa

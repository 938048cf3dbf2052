// Enhanced (multi-frame) DICOM: each frame's geometry from the functional group sequences.
#include "io/dicom_frames.h"

#include <gdcmReader.h>

#include <algorithm>

#include "io/dicom_items.h"
#include "io/load_failure.h"

namespace ewa {

namespace {

const gdcm::Tag kPlanePosition(0x0020, 0x9113);
const gdcm::Tag kPlaneOrientation(0x0020, 0x9116);
const gdcm::Tag kPixelMeasures(0x0028, 0x9110);
const gdcm::Tag kPosition(0x0020, 0x0032);
const gdcm::Tag kOrientation(0x0020, 0x0037);
const gdcm::Tag kPixelSpacing(0x0028, 0x0030);
const gdcm::Tag kPixelData(0x7fe0, 0x0010);

// Plane position, orientation and pixel spacing of a functional groups item, where it has them.
void applyGroups(DicomItems& items, const gdcm::DataSet* groups, DicomSlice& s) {
  const std::vector<double> p = dicomElementNumbers(items.first(groups, kPlanePosition), kPosition);
  if (p.size() == 3) s.position = {p[0], p[1], p[2]}, s.hasPosition = true;
  const std::vector<double> o =
      dicomElementNumbers(items.first(groups, kPlaneOrientation), kOrientation);
  if (o.size() == 6) std::copy(o.begin(), o.end(), s.orientation.begin()), s.hasOrientation = true;
  const std::vector<double> sp =
      dicomElementNumbers(items.first(groups, kPixelMeasures), kPixelSpacing);
  if (sp.size() == 2 && sp[0] > 0.0 && sp[1] > 0.0)
    s.rowSpacing = sp[0], s.columnSpacing = sp[1], s.hasSpacing = true;
}

}  // namespace

std::vector<DicomSlice> dicomFrameSlices(const DicomSlice& file) {
  gdcm::Reader reader;
  reader.SetFileName(file.file.c_str());
  if (!reader.ReadUpToTag(kPixelData)) failLoad(file.file, "GDCM cannot read the header");
  const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
  DicomItems items;
  const gdcm::SequenceOfItems* perFrame = items.sequence(ds, kPerFrameFunctionalGroups);
  if (!perFrame || int64_t(perFrame->GetNumberOfItems()) != file.frames) return {};
  // The file's own values, then the shared groups', then each frame's.
  DicomSlice shared = file;
  shared.frames = 1;
  applyGroups(items, items.first(&ds, kSharedFunctionalGroups), shared);
  std::vector<DicomSlice> frames;
  for (size_t f = 0; f < perFrame->GetNumberOfItems(); ++f) {
    DicomSlice s = shared;
    s.frame = int64_t(f);
    s.hasPosition = false;
    applyGroups(items, &perFrame->GetItem(f + 1).GetNestedDataSet(), s);
    if (!s.hasPosition) return {};  // not a stack of planes
    if (!frames.empty() && (s.rowSpacing != frames.front().rowSpacing ||
                            s.columnSpacing != frames.front().columnSpacing))
      failLoad(file.file, "PixelSpacing differs between frames");
    frames.push_back(s);
  }
  return frames;
}

}  // namespace ewa

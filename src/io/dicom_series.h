// DICOM series in a folder: which files belong together and in what order (through GDCM's Scanner).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "io/dicom_gaps.h"

namespace ewa {

// One image file of a series, with the header values the volume is built from.
struct DicomSlice {
  std::string file;
  glm::dvec3 position{0.0};                             // ImagePositionPatient
  std::array<double, 6> orientation{1, 0, 0, 0, 1, 0};  // ImageOrientationPatient
  bool hasPosition = false, hasOrientation = false;
  int64_t rows = 0, columns = 0;
  double rowSpacing = 1.0, columnSpacing = 1.0;  // PixelSpacing: between rows, between columns
  bool hasSpacing = false;
  int64_t frames = 1;    // NumberOfFrames
  int64_t frame = 0;     // of a multi-frame file opened frame by frame (dicom_frames.h): its frame
  int64_t instance = 0;  // InstanceNumber (0 when absent): orders volumes at the same positions
  // Where slices without ImagePositionPatient go (dicom_unplaced.h); 0 when absent.
  double sliceLocation = 0.0, sliceThickness = 0.0, spacingBetweenSlices = 0.0;
  bool hasSliceLocation = false;
  // ACR-NEMA's retired Image Position (0020,0030) and Image Orientation (0020,0035): the same
  // numbers in the equipment's own axes, read only when no slice has ImagePositionPatient.
  glm::dvec3 retiredPosition{0.0};
  std::array<double, 6> retiredOrientation{1, 0, 0, 0, 1, 0};
  bool hasRetiredPosition = false, hasRetiredOrientation = false;
  // Pixel module values, checked before GDCM decodes (its reader asserts on some bad ones).
  int64_t samplesPerPixel = 1, bitsAllocated = 0, bitsStored = 0, highBit = 0, representation = 0;
  int64_t planarConfiguration = 0;  // 0 when absent; -1 when present but not a number
  std::string photometric;          // PhotometricInterpretation, trimmed; empty when absent
  std::string
      sopInstanceUid;   // SOPInstanceUID, trimmed: tells a file's copies (dicom_duplicates.h)
  bool named = false;   // the file the user named (scanDicomFolder's namedFile)
  bool mosaic = false;  // ImageType (0008,0008) holds MOSAIC: a Siemens mosaic (dicom_mosaic.h)
};

struct DicomSeries {
  std::string uid;  // SeriesInstanceUID; a part split off one (splitDicomSeries): UID#2, ...
  std::string description;
  std::string partOf;  // the series a part was split off, and why ("64 x 64, another orientation")
  std::vector<DicomSlice> slices;
};

// Reads the headers of the regular files in `folder` (with `below`, in its subfolders too, as a
// CD's DICOMDIR tree holds them: not through links to folders, at most kDicomMaxDepth levels
// down and kDicomMaxEntries entries, else LoadError) and groups the images (files with Rows and
// Columns) by SeriesInstanceUID, largest series first. Files that are not DICOM are skipped;
// so are corrupt or cut short ones (a stray broken copy beside a series), each one's problem
// added to `unreadable` as `path: problem`, but for `namedFile`, whose problem throws.
// `fileSeries` gets the series of `namedFile` when that is one of them.
std::vector<DicomSeries> scanDicomFolder(const std::string& folder, const std::string& namedFile,
                                         std::string* fileSeries, bool below = false,
                                         std::vector<std::string>* unreadable = nullptr);
constexpr int kDicomMaxDepth = 8;
constexpr size_t kDicomMaxEntries = 100000;

// The unit normal (row x column cosines) of an orientation; (0, 0, 1) for a degenerate one
// (sortDicomSlices' error to report).
glm::dvec3 dicomSliceNormal(const std::array<double, 6>& orientation);

// True when the ImageOrientationPatient cosines of `a` and `b` agree within 1e-3 each.
bool sameDicomOrientation(const DicomSlice& a, const DicomSlice& b);

// Splits each series into the volumes it holds, as a series may mix a localizer's three planes,
// images of another size or several multi-frame files: single-frame slices of one size and
// orientation stack together, and each multi-frame file is a volume of its own. A series' largest
// part keeps its UID, the others (largest first) are named UID#2, UID#3, ... (no UID holds a
// '#'), with partOf saying why. Series stay largest first.
void splitDicomSeries(std::vector<DicomSeries>& all);

// The UID of the series holding the slice marked `named`; empty when none does.
std::string namedSeries(const std::vector<DicomSeries>& all);

// Numbers of a multi-valued DICOM string ("a\\b\\c"); empty when any is not a number.
std::vector<double> dicomNumbers(const char* text);

// Sorts the slices by their position along the slice normal (row x column cosines), never by
// name. Throws LoadError naming `path` when slices share a position or their orientations
// differ. Returns the slice step vector (mean of the steps between neighbours) and adds
// warnings (uneven spacing, missing slices) to `notes`. With `planes`, uneven steps are made
// regular (else it is cleared): steps that are whole multiples of the series' step
// (missingSlicesAfter, dicom_gaps.h) get the missing slices filled in (planesWithMissing),
// other uneven steps a regular stack resampled from the slices (regularPlanes); `planes` then
// says how to make each plane from the sorted slices (mixPlanes), the step returned is the
// regular one and the warning says so. Without it, the volume is drawn evenly spaced.
glm::dvec3 sortDicomSlices(const std::string& path, std::vector<DicomSlice>& slices,
                           std::vector<std::string>& notes,
                           std::vector<PlaneMix>* planes = nullptr);

// Whether the series scanner (gdcm::Scanner) reads this tag from every file; its string filter
// asserts on a VR it has no conversion for (UV, found by fuzzing), so dicom_guard checks these
// tags' VRs against the dictionary before GDCM reads the file.
bool isScannedDicomTag(uint16_t group, uint16_t element);

}  // namespace ewa

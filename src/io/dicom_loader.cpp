// DICOM series (a folder or any file of it) through GDCM: sorted slices, rescale, orientation.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

#include "io/byte_order.h"
#include "io/dicom_dose_grid.h"
#include "io/dicom_duplicates.h"
#include "io/dicom_frames.h"
#include "io/dicom_gaps.h"
#include "io/dicom_mosaic.h"
#include "io/dicom_pixels.h"
#include "io/dicom_series.h"
#include "io/dicom_unplaced.h"
#include "io/dicom_volumes.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

const DicomSeries& pickSeries(const std::string& path, const std::vector<DicomSeries>& all,
                              const std::string& wanted, const std::string& fileSeries) {
  const std::string uid = !wanted.empty() ? wanted : fileSeries;
  if (uid.empty()) return all.front();
  for (const DicomSeries& s : all)
    if (s.uid == uid) return s;
  std::string known;
  for (const DicomSeries& s : all) known += (known.empty() ? "" : ", ") + s.uid;
  failLoad(path, "no series " + quoteText(uid, 80) + " here (series: " + known + ")");
}

// Notes for the files a scan left out (`prefix` "warning: " for corrupt ones): the first few
// named, then a count of `more`, so a folder of broken files does not print a line each.
void noteSkipped(const std::vector<std::string>& skipped, const std::string& prefix,
                 const std::string& more, std::vector<std::string>& notes) {
  constexpr size_t kNamed = 3;
  for (size_t i = 0; i < skipped.size() && i < kNamed; ++i)
    notes.push_back(prefix + "skipped " + skipped[i]);
  if (skipped.size() > kNamed)
    notes.push_back(prefix + "skipped " + std::to_string(skipped.size() - kNamed) + " more " +
                    more);
}

// How much a series holds, for the series list: its slices, or a multi-frame file's frames.
std::string seriesSize(const DicomSeries& s) {
  const int64_t frames = s.slices.size() == 1 ? s.slices.front().frames : 1;
  if (frames > 1) return std::to_string(frames) + " frames";
  return std::to_string(s.slices.size()) + (s.slices.size() == 1 ? " slice" : " slices");
}

// A mosaic's grid: its tiles' size, their count, their spacing along the normal from the
// first plane (the last stored one when the slices run against row x column).
void placeMosaic(const DicomMosaic& m, VolumeLayout& layout) {
  layout.dims = {m.tileColumns, m.tileRows, m.count};
  layout.spacing.z = m.spacing;
  layout.origin =
      m.first + (m.reversed ? -double(m.count - 1) * m.spacing : 0.0) * layout.direction[2];
  layout.notes.push_back("Siemens mosaic: " + std::to_string(m.count) + " slices of " +
                         std::to_string(m.tileColumns) + " x " + std::to_string(m.tileRows) +
                         " from its " + std::to_string(m.perRow) + " x " +
                         std::to_string(m.perRow) + " tiles (CSA NumberOfImagesInMosaic)" +
                         (m.spacingAssumed ? ", slice spacing 1 assumed" : ""));
}

// The folder of `file` relative to `root` (where a series lies in a CD's tree).
std::string relativeFolder(const std::string& file, const std::string& root) {
  const std::filesystem::path rel =
      std::filesystem::path(file).parent_path().lexically_relative(root);
  return rel.empty() ? std::string(".") : rel.generic_string();
}

}  // namespace

Volume loadDicom(const std::string& path, const std::string& seriesUid, int channel, int frame) {
  std::error_code ec;
  const std::filesystem::path named(path);
  // A CD's DICOMDIR names the images in the folders below it: opened as that folder is.
  const bool dicomdir = toLower(named.filename().string()) == "dicomdir";
  const bool directory = std::filesystem::is_directory(path, ec);
  const bool folder = dicomdir || directory;
  std::string dir = directory ? path : named.parent_path().string();
  if (dir.empty()) dir = ".";
  if (!folder && !looksLikeDicom(path))
    failLoad(path,
             "not a DICOM file (no 'DICM' at byte 128, and no data set of group 0008 at "
             "byte 0)");
  std::string fileSeries;
  std::vector<std::string> unreadable;
  std::vector<DicomSeries> all =
      scanDicomFolder(dir, folder ? std::string() : path, &fileSeries, false, &unreadable);
  // No image in the folder itself: the images of the folders below it (a CD's tree; its
  // list of broken files, the folder's own among them, replaces the folder's).
  const bool below = folder && all.empty();
  if (below) all = scanDicomFolder(dir, std::string(), nullptr, true, &unreadable);
  std::vector<std::string> copies;
  dropDuplicateImages(all, copies);
  // A series mixing sizes, orientations or multi-frame files: each volume a series of its own.
  splitDicomSeries(all);
  if (!fileSeries.empty()) fileSeries = namedSeries(all);
  if (all.empty() && !unreadable.empty())
    failLoad(path, "no readable DICOM image: " + unreadable.front() +
                       (unreadable.size() > 1
                            ? " (and " + std::to_string(unreadable.size() - 1) + " more)"
                            : ""));
  if (all.empty())
    failLoad(path, folder ? "a directory with no DICOM image or TIFF file, in it or below it"
                          : "not a DICOM image");
  if (!folder && fileSeries.empty() && seriesUid.empty())
    failLoad(path, "not a DICOM image (no Rows and Columns)");
  const DicomSeries& chosen = pickSeries(path, all, seriesUid, fileSeries);

  VolumeLayout layout;
  layout.patientFrame = true;
  layout.unit = "mm";  // DICOM's lengths are millimetres
  noteSkipped(unreadable, "warning: ", "corrupt or truncated files", layout.notes);
  noteSkipped(copies, "", "copies of images already in the series", layout.notes);
  if (all.size() > 1 || below)  // below: where the series lies, even alone
    for (const DicomSeries& s : all) {
      const std::string label =
          seriesSize(s) + (s.description.empty() ? "" : ", " + s.description) +
          (s.partOf.empty() ? "" : " (" + s.partOf + ")") +
          (below ? " in " + quoteText(relativeFolder(s.slices.front().file, dir), 80) : "");
      layout.notes.push_back("series " + s.uid + ": " + label +
                             (&s == &chosen ? " (open)" : " (--series UID opens it)"));
      layout.seriesChoices.push_back({s.uid, label, &s == &chosen});
    }
  // One size and orientation, or one multi-frame file (splitDicomSeries).
  std::vector<DicomSlice> slices = chosen.slices;
  // An enhanced multi-frame file: its frames as slices, ordered by their own positions (the
  // file is still read once; its frames are put in that order).
  const DicomSlice whole = slices.front();
  std::vector<DicomSlice> frames;
  if (slices.size() == 1 && whole.frames > 1) frames = dicomFrameSlices(whole);
  if (slices.size() == 1 && whole.frames > 1 && frames.empty()) {
    frames = doseGridFrameSlices(whole);
    if (!frames.empty())
      layout.notes.push_back("RT Dose: frames placed by GridFrameOffsetVector (3004,000C)");
  }
  glm::dvec3 step(0.0);
  std::vector<PlaneMix> planes;  // uneven steps: the regular planes made below, else empty
  // A Siemens mosaic (or a series of them, one a volume): its tiles are the slices.
  std::optional<DicomMosaic> mosaic = frames.empty() ? dicomMosaic(whole) : std::nullopt;
  if (mosaic) {
    slices = {selectMosaicVolume(path, std::move(slices), frame, layout.notes, &layout.frameCount)};
    mosaic = dicomMosaic(slices.front());  // the volume's own
  } else if (!frames.empty()) {
    // An enhanced file of several volumes (diffusion, time points): the one asked for.
    frames = selectDicomVolume(path, std::move(frames), frame, layout.notes, &layout.frameCount);
    try {
      step = sortDicomSlices(path, frames, layout.notes, &planes);
      slices = frames;
    } catch (const LoadError& e) {
      // Frames at one place (a time series) or turned: kept whole, as a plain multi-frame file
      // is, the note saying why.
      frames.clear();
      const std::string what = e.what();
      const size_t colon = what.find(": ");
      layout.notes.push_back("frames kept in stored order, not a stack of slices: " +
                             (colon == std::string::npos ? what : what.substr(colon + 2)));
    }
  } else {
    // No positions (ACR-NEMA): given some, and no anatomical labels without an orientation.
    const UnplacedSlices placed = placeUnplacedSlices(slices, layout.notes);
    if (placed.orientationAssumed || placed.equipmentAxes) layout.patientFrame = false;
    slices = selectDicomVolume(path, std::move(slices), frame, layout.notes, &layout.frameCount);
    if (const auto cine = stackOnePosition(slices, layout.notes))
      step = *cine;
    else
      step = sortDicomSlices(path, slices, layout.notes, &planes);
  }
  layout.frame = frame;  // in range: selectDicomVolume checked it
  const DicomSlice& base = slices.front();
  const int64_t stored = int64_t(slices.size()) * base.frames;
  layout.dims = {base.columns, base.rows, planes.empty() ? stored : int64_t(planes.size())};
  if (!base.hasSpacing) layout.notes.push_back("no PixelSpacing: 1 assumed");
  if (base.samplesPerPixel > 1)
    layout.notes.push_back((base.photometric.rfind("YBR", 0) == 0
                                ? "RGB (from " + base.photometric + "): "
                                : std::string("RGB: ")) +
                           std::to_string(base.samplesPerPixel) + " channels; showing channel " +
                           std::to_string(channel) + " (--channel N picks another)");
  if (base.samplesPerPixel > 1) {
    layout.channel = channel;  // checked against the samples when the pixels are read
    layout.channelCount = int(std::min<int64_t>(base.samplesPerPixel, 1 << 20));
  }
  layout.spacing = {base.columnSpacing, base.rowSpacing, 1.0};
  const glm::dvec3 row(base.orientation[0], base.orientation[1], base.orientation[2]);
  const glm::dvec3 column(base.orientation[3], base.orientation[4], base.orientation[5]);
  layout.direction[0] = row;
  layout.direction[1] = column;
  layout.direction[2] = glm::cross(row, column);
  if (slices.size() > 1) {
    layout.spacing.z = glm::length(step);
    layout.direction[2] = step / layout.spacing.z;  // tilted gantry: not the normal
  } else if (base.frames > 1) {
    layout.notes.push_back("multi-frame file: slice spacing 1 assumed");
  }
  layout.origin = base.position;
  if (mosaic) placeMosaic(*mosaic, layout);
  // Doubles while rescaling: the planes made, and the stored ones they are made from.
  uint64_t total = dataByteCount(path, layout.dims, FileScalar::Float32);
  if (!planes.empty())
    total += dataByteCount(path, {base.columns, base.rows, stored}, FileScalar::Float32);
  checkAllocation(path, total * 2, "DICOM values");

  std::vector<double> values;
  bool integral = true, sameRescale = true, sameType = true;
  double slope0 = 0.0, intercept0 = 0.0;
  gdcm::PixelFormat::ScalarType type0 = gdcm::PixelFormat::UNKNOWN;
  const std::vector<DicomSlice> wholeFile{whole};
  const std::vector<DicomSlice>& files = frames.empty() ? slices : wholeFile;
  for (size_t i = 0; i < files.size(); ++i) {
    const SlicePixels px = readSlice(files[i], channel);
    const bool intType =
        px.type != gdcm::PixelFormat::FLOAT32 && px.type != gdcm::PixelFormat::FLOAT64;
    integral = integral && intType && px.slope == std::round(px.slope) &&
               px.intercept == std::round(px.intercept);
    if (i == 0) slope0 = px.slope, intercept0 = px.intercept, type0 = px.type;
    sameType = sameType && px.type == type0;
    sameRescale = sameRescale && px.slope == slope0 && px.intercept == intercept0;
    values.insert(values.end(), px.values.begin(), px.values.end());
  }
  if (mosaic) values = mosaicPlanes(values, whole.columns, *mosaic);
  if (!frames.empty()) {
    // The file's frames in stored order, put in the slices' order.
    const size_t plane = size_t(whole.columns) * size_t(whole.rows);
    std::vector<double> ordered;
    ordered.reserve(values.size());
    for (const DicomSlice& s : slices)
      ordered.insert(ordered.end(), values.begin() + ptrdiff_t(size_t(s.frame) * plane),
                     values.begin() + ptrdiff_t(size_t(s.frame + 1) * plane));
    values.swap(ordered);
  }
  if (!planes.empty())
    mixPlanes(values, size_t(base.columns) * size_t(base.rows), planes, integral && sameRescale);
  if (!sameRescale) {
    integral = false;  // float32: per-slice scales rarely land on integers
    layout.notes.push_back("rescale slope or intercept differ between slices: float32");
  }
  // The stored type when nothing was rescaled, else the narrowest that holds the values.
  const bool identity = sameRescale && slope0 == 1.0 && intercept0 == 0.0 && sameType;
  if (identity && type0 == gdcm::PixelFormat::UINT8)
    layout.type = FileScalar::UInt8;
  else if (identity && type0 == gdcm::PixelFormat::UINT16)
    layout.type = FileScalar::UInt16;
  else if (identity && (type0 == gdcm::PixelFormat::INT16 || type0 == gdcm::PixelFormat::INT8))
    layout.type = FileScalar::Int16;
  else
    layout.type = fittingType(values, integral);
  layout.bigEndian = hostIsBigEndian();
  for (const DicomSlice& s : files) layout.sourceFiles.push_back(s.file);
  return makeVolume(path, layout, encodeValues(values, layout.type));
}

}  // namespace ewa

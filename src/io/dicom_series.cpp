// DICOM series discovery with gdcm::Scanner (headers only) and slice ordering along the normal.
#include "io/dicom_series.h"

#include <gdcmScanner.h>
#include <gdcmTrace.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <optional>

#include "io/dicom_gaps.h"
#include "io/dicom_guard.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

const gdcm::Tag kSeriesUid(0x0020, 0x000e);
const gdcm::Tag kSeriesDescription(0x0008, 0x103e);
const gdcm::Tag kPosition(0x0020, 0x0032);
const gdcm::Tag kOrientation(0x0020, 0x0037);
const gdcm::Tag kRows(0x0028, 0x0010);
const gdcm::Tag kColumns(0x0028, 0x0011);
const gdcm::Tag kPixelSpacing(0x0028, 0x0030);
const gdcm::Tag kFrames(0x0028, 0x0008);
const gdcm::Tag kSamplesPerPixel(0x0028, 0x0002);
const gdcm::Tag kBitsAllocated(0x0028, 0x0100);
const gdcm::Tag kBitsStored(0x0028, 0x0101);
const gdcm::Tag kHighBit(0x0028, 0x0102);
const gdcm::Tag kRepresentation(0x0028, 0x0103);
const gdcm::Tag kPhotometric(0x0028, 0x0004);
const gdcm::Tag kPlanarConfiguration(0x0028, 0x0006);
const gdcm::Tag kInstance(0x0020, 0x0013);
const gdcm::Tag kSliceLocation(0x0020, 0x1041);
const gdcm::Tag kSliceThickness(0x0018, 0x0050);
const gdcm::Tag kSpacingBetweenSlices(0x0018, 0x0088);
const gdcm::Tag kSopInstance(0x0008, 0x0018);
const gdcm::Tag kRetiredPosition(0x0020, 0x0030);
const gdcm::Tag kRetiredOrientation(0x0020, 0x0035);
const gdcm::Tag kImageType(0x0008, 0x0008);
// What the scanner reads from every file (and dicom_guard checks first: isScannedDicomTag).
const gdcm::Tag kScannedTags[] = {kSeriesUid,
                                  kSeriesDescription,
                                  kPosition,
                                  kOrientation,
                                  kRows,
                                  kColumns,
                                  kPixelSpacing,
                                  kFrames,
                                  kSamplesPerPixel,
                                  kBitsAllocated,
                                  kBitsStored,
                                  kHighBit,
                                  kRepresentation,
                                  kPhotometric,
                                  kPlanarConfiguration,
                                  kInstance,
                                  kSliceLocation,
                                  kSliceThickness,
                                  kSpacingBetweenSlices,
                                  kRetiredPosition,
                                  kRetiredOrientation,
                                  kSopInstance,
                                  kImageType};

int64_t integer(const char* text) {
  int64_t v = 0;
  return text && parseInt64(trim(std::string(text)), v) ? v : 0;
}

// The regular files of `folder` (with `below`, of its subfolders too, within kDicomMaxDepth and
// kDicomMaxEntries) whose element structure may go to GDCM, sorted by path. A corrupt or cut
// short file is left out and its one-line problem added to `unreadable`, unless it is
// `namedFile`, whose problem is the load's.
std::vector<std::string> dicomCandidates(const std::string& folder, bool below,
                                         const std::string& namedFile,
                                         std::vector<std::string>& unreadable) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  std::error_code ec;
  const auto consider = [&](const fs::directory_entry& entry) {
    std::error_code statError;  // a dangling link is skipped, not the listing's failure
    if (!entry.is_regular_file(statError)) return;
    const std::string file = entry.path().string();
    try {
      // GDCM sizes buffers by element lengths: only files whose lengths fit reach it.
      if (checkDicomStructure(file) == DicomStructure::Plausible) files.push_back(file);
    } catch (const LoadError& e) {
      std::error_code same;
      if (!namedFile.empty() && fs::equivalent(file, namedFile, same)) throw;
      unreadable.push_back(e.what());
    }
  };
  if (below) {
    size_t entries = 0;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    for (const fs::recursive_directory_iterator end; !ec && it != end; it.increment(ec)) {
      if (++entries > kDicomMaxEntries)
        failLoad(folder, "more than " + std::to_string(kDicomMaxEntries) +
                             " files and folders below it: open the series' own folder");
      if (it.depth() + 1 >= kDicomMaxDepth) it.disable_recursion_pending();
      consider(*it);
    }
  } else {
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
      consider(*it);
  }
  if (ec) failLoad(folder, "cannot list the folder (" + ec.message() + ")");
  std::sort(files.begin(), files.end());
  std::sort(unreadable.begin(), unreadable.end());  // "path: problem": by path
  return files;
}

}  // namespace

bool isScannedDicomTag(uint16_t group, uint16_t element) {
  for (const gdcm::Tag& t : kScannedTags)
    if (t.GetGroup() == group && t.GetElement() == element) return true;
  return false;
}

std::vector<double> dicomNumbers(const char* text) {
  std::vector<double> out;
  if (!text) return out;
  for (const std::string& part : splitWords(std::string(text), "\\")) {
    double v = 0.0;
    if (!parseDouble(trim(part), v) || !std::isfinite(v)) return {};
    out.push_back(v);
  }
  return out;
}

std::vector<DicomSeries> scanDicomFolder(const std::string& folder, const std::string& namedFile,
                                         std::string* fileSeries, bool below,
                                         std::vector<std::string>* unreadable) {
  // GDCM reports on stderr by default; our errors are one line each, from us.
  gdcm::Trace::WarningOff();
  gdcm::Trace::ErrorOff();
  gdcm::Trace::DebugOff();
  std::vector<std::string> problems;
  const std::vector<std::string> files = dicomCandidates(folder, below, namedFile, problems);
  if (unreadable) *unreadable = std::move(problems);
  std::error_code ec;

  gdcm::Scanner scanner;
  for (const gdcm::Tag& t : kScannedTags) scanner.AddTag(t);
  if (!files.empty() && !scanner.Scan(files)) failLoad(folder, "cannot read the DICOM headers");

  std::map<std::string, DicomSeries> byUid;
  for (const std::string& file : files) {
    if (!scanner.IsKey(file.c_str())) continue;
    DicomSlice s;
    s.file = file;
    s.rows = integer(scanner.GetValue(file.c_str(), kRows));
    s.columns = integer(scanner.GetValue(file.c_str(), kColumns));
    if (s.rows <= 0 || s.columns <= 0) continue;  // not an image (DICOMDIR, report, ...)
    const std::vector<double> p = dicomNumbers(scanner.GetValue(file.c_str(), kPosition));
    if (p.size() == 3) s.position = {p[0], p[1], p[2]}, s.hasPosition = true;
    const std::vector<double> o = dicomNumbers(scanner.GetValue(file.c_str(), kOrientation));
    if (o.size() == 6)
      std::copy(o.begin(), o.end(), s.orientation.begin()), s.hasOrientation = true;
    const std::vector<double> rp = dicomNumbers(scanner.GetValue(file.c_str(), kRetiredPosition));
    if (rp.size() == 3) s.retiredPosition = {rp[0], rp[1], rp[2]}, s.hasRetiredPosition = true;
    const std::vector<double> ro =
        dicomNumbers(scanner.GetValue(file.c_str(), kRetiredOrientation));
    if (ro.size() == 6)
      std::copy(ro.begin(), ro.end(), s.retiredOrientation.begin()), s.hasRetiredOrientation = true;
    const std::vector<double> sp = dicomNumbers(scanner.GetValue(file.c_str(), kPixelSpacing));
    if (sp.size() == 2 && sp[0] > 0.0 && sp[1] > 0.0)
      s.rowSpacing = sp[0], s.columnSpacing = sp[1], s.hasSpacing = true;
    s.frames = std::max<int64_t>(1, integer(scanner.GetValue(file.c_str(), kFrames)));
    s.instance = integer(scanner.GetValue(file.c_str(), kInstance));
    // A tag holding one number, else nullopt.
    const auto single = [&](const gdcm::Tag& tag) -> std::optional<double> {
      const std::vector<double> v = dicomNumbers(scanner.GetValue(file.c_str(), tag));
      return v.size() == 1 ? std::optional<double>(v[0]) : std::nullopt;
    };
    if (const auto at = single(kSliceLocation)) s.sliceLocation = *at, s.hasSliceLocation = true;
    if (const auto thick = single(kSliceThickness); thick && *thick > 0.0)
      s.sliceThickness = *thick;
    if (const auto between = single(kSpacingBetweenSlices); between && *between > 0.0)
      s.spacingBetweenSlices = *between;
    if (const char* spp = scanner.GetValue(file.c_str(), kSamplesPerPixel))
      s.samplesPerPixel = integer(spp);
    s.bitsAllocated = integer(scanner.GetValue(file.c_str(), kBitsAllocated));
    s.bitsStored = integer(scanner.GetValue(file.c_str(), kBitsStored));
    s.highBit = integer(scanner.GetValue(file.c_str(), kHighBit));
    s.representation = integer(scanner.GetValue(file.c_str(), kRepresentation));
    if (const char* pc = scanner.GetValue(file.c_str(), kPlanarConfiguration)) {
      int64_t v = 0;
      s.planarConfiguration = parseInt64(trim(std::string(pc)), v) ? v : -1;
    }
    if (const char* pi = scanner.GetValue(file.c_str(), kPhotometric)) s.photometric = trim(pi);
    if (const char* sop = scanner.GetValue(file.c_str(), kSopInstance))
      s.sopInstanceUid = trim(sop);
    if (const char* type = scanner.GetValue(file.c_str(), kImageType))
      for (const std::string& word : splitWords(std::string(type), "\\"))
        s.mosaic = s.mosaic || trim(word) == "MOSAIC";
    const char* uid = scanner.GetValue(file.c_str(), kSeriesUid);
    DicomSeries& series = byUid[uid ? trim(std::string(uid)) : std::string()];
    series.uid = uid ? trim(std::string(uid)) : std::string();
    if (const char* d = scanner.GetValue(file.c_str(), kSeriesDescription))
      series.description = trim(std::string(d));
    if (!namedFile.empty() && std::filesystem::equivalent(file, namedFile, ec)) {
      s.named = true;
      if (fileSeries) *fileSeries = series.uid;
    }
    series.slices.push_back(std::move(s));
  }
  std::vector<DicomSeries> out;
  for (auto& entry : byUid) out.push_back(std::move(entry.second));
  std::stable_sort(out.begin(), out.end(), [](const DicomSeries& a, const DicomSeries& b) {
    return a.slices.size() > b.slices.size();
  });
  return out;
}

glm::dvec3 dicomSliceNormal(const std::array<double, 6>& o) {
  const glm::dvec3 n = glm::cross(glm::dvec3(o[0], o[1], o[2]), glm::dvec3(o[3], o[4], o[5]));
  return glm::length(n) > 1e-6 ? glm::normalize(n) : glm::dvec3(0, 0, 1);
}

bool sameDicomOrientation(const DicomSlice& a, const DicomSlice& b) {
  for (size_t i = 0; i < 6; ++i)
    if (std::fabs(a.orientation[i] - b.orientation[i]) > 1e-3) return false;
  return true;
}

namespace {

// Why `part` is not the series' main part `main`: its size, its orientation, its frames.
std::string partReason(const DicomSlice& main, const DicomSlice& part) {
  std::string why;
  auto add = [&](const std::string& what) { why += (why.empty() ? "" : ", ") + what; };
  if (part.columns != main.columns || part.rows != main.rows)
    add(std::to_string(part.columns) + " x " + std::to_string(part.rows));
  if (!sameDicomOrientation(part, main)) add("another orientation");
  if (part.frames > 1) add(main.frames > 1 ? "another multi-frame file" : "a multi-frame file");
  return why.empty() ? std::string("another volume") : why;
}

}  // namespace

void splitDicomSeries(std::vector<DicomSeries>& all) {
  std::vector<DicomSeries> out;
  for (DicomSeries& series : all) {
    if (series.slices.empty()) continue;
    std::vector<std::vector<DicomSlice>> parts;
    for (DicomSlice& s : series.slices) {
      auto fits = [&](const std::vector<DicomSlice>& part) {
        const DicomSlice& f = part.front();
        return s.frames == 1 && f.frames == 1 && s.columns == f.columns && s.rows == f.rows &&
               sameDicomOrientation(s, f);
      };
      const auto it = std::find_if(parts.begin(), parts.end(), fits);
      const size_t n = size_t(it - parts.begin());  // it is invalid once parts grows
      if (n == parts.size()) parts.emplace_back();
      parts[n].push_back(std::move(s));
    }
    std::stable_sort(parts.begin(), parts.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    const DicomSlice main = parts.front().front();  // parts are moved out below
    for (size_t n = 0; n < parts.size(); ++n) {
      DicomSeries part;
      part.uid = n == 0 ? series.uid : series.uid + "#" + std::to_string(n + 1);
      part.description = series.description;
      if (n > 0) part.partOf = "part of " + series.uid + ": " + partReason(main, parts[n].front());
      part.slices = std::move(parts[n]);
      out.push_back(std::move(part));
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const DicomSeries& a, const DicomSeries& b) {
    return a.slices.size() > b.slices.size();
  });
  all = std::move(out);
}

std::string namedSeries(const std::vector<DicomSeries>& all) {
  for (const DicomSeries& series : all)
    for (const DicomSlice& s : series.slices)
      if (s.named) return series.uid;
  return {};
}

glm::dvec3 sortDicomSlices(const std::string& path, std::vector<DicomSlice>& slices,
                           std::vector<std::string>& notes, std::vector<PlaneMix>* planes) {
  if (planes) planes->clear();
  if (slices.size() < 2) return glm::dvec3(0.0);
  const DicomSlice& first = slices.front();
  for (const DicomSlice& s : slices) {
    if (!s.hasPosition || !s.hasOrientation)
      failLoad(s.file,
               "no ImagePositionPatient or ImageOrientationPatient: cannot order the "
               "slices of the series");
    if (!sameDicomOrientation(s, first))
      failLoad(s.file, "ImageOrientationPatient differs from the series' other slices");
  }
  const glm::dvec3 row(first.orientation[0], first.orientation[1], first.orientation[2]);
  const glm::dvec3 column(first.orientation[3], first.orientation[4], first.orientation[5]);
  const glm::dvec3 normal = glm::cross(row, column);
  if (glm::length(normal) < 1e-6) failLoad(first.file, "degenerate ImageOrientationPatient");
  std::stable_sort(slices.begin(), slices.end(), [&](const DicomSlice& a, const DicomSlice& b) {
    return glm::dot(a.position, normal) < glm::dot(b.position, normal);
  });
  std::vector<double> gaps;
  for (size_t i = 1; i < slices.size(); ++i) {
    const double gap = glm::dot(slices[i].position - slices[i - 1].position, normal);
    if (gap < 1e-6)
      failLoad(path, "two slices share one position (" + slices[i - 1].file + " and " +
                         slices[i].file + "): more than one volume in the series?");
    gaps.push_back(gap);
  }
  const glm::dvec3 span = slices.back().position - slices.front().position;
  if (planes) {
    const std::vector<int64_t> missingAfter = missingSlicesAfter(gaps, slices.size());
    if (!missingAfter.empty()) {
      *planes = planesWithMissing(missingAfter);
      const size_t missing = planes->size() - slices.size();
      const double step = *std::min_element(gaps.begin(), gaps.end());
      notes.push_back("warning: " + std::to_string(missing) + " missing slice" +
                      (missing > 1 ? "s" : "") + " (gaps of whole multiples of the step, " +
                      std::to_string(step) +
                      "): filled in by linear interpolation between their neighbours");
      return span / double(planes->size() - 1);
    }
  }
  std::vector<double> sorted = gaps;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double lo = sorted.front(), hi = sorted.back();
  const bool uneven = hi - lo > 0.01 * median;
  std::string done = "drawn evenly spaced";
  if (planes && uneven) {
    std::vector<double> at;
    for (const DicomSlice& s : slices) at.push_back(glm::dot(s.position, normal));
    // How far drawing the slices evenly spaced would move one from its place.
    double misplaced = 0.0;
    for (size_t i = 0; i < at.size(); ++i)
      misplaced = std::max(misplaced,
                           std::abs(at[i] - at.front() -
                                    (at.back() - at.front()) * double(i) / double(at.size() - 1)));
    // The stack resampled onto regular steps, so that it keeps its true shape; a slice or two
    // a hair off (rounded positions) is drawn evenly spaced, unblurred.
    if (misplaced > kMaxMisplacedSlice * median) *planes = regularPlanes(at);
    if (!planes->empty())
      done = "resampled onto " + std::to_string(planes->size()) + " slices " +
             std::to_string((at.back() - at.front()) / double(planes->size() - 1)) +
             " apart, each linear between the slices either side";
  }
  if (hi > 1.5 * median) {
    notes.push_back("warning: a gap of " + std::to_string(hi) + " between slices where most are " +
                    std::to_string(median) + ": missing slices? " + done);
  } else if (uneven) {
    notes.push_back("warning: uneven slice spacing (" + std::to_string(lo) + " to " +
                    std::to_string(hi) + "); " + done);
  }
  if (planes && !planes->empty()) return span / double(planes->size() - 1);
  // The mean step: along the normal, or oblique when the gantry was tilted.
  return span / double(slices.size() - 1);
}

}  // namespace ewa

// DICOM series (a folder or any file of it) through GDCM: sorted slices, rescale, orientation.
#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmSequenceOfFragments.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <limits>
#include <map>

#include "io/byte_order.h"
#include "io/dicom_series.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/text_fields.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// One slice's pixels decoded (any transfer syntax GDCM decodes) as doubles after rescale.
struct SlicePixels {
  std::vector<double> values;
  double slope = 1.0, intercept = 0.0;
  gdcm::PixelFormat::ScalarType type = gdcm::PixelFormat::UNKNOWN;
};

template <typename T>
void appendValues(const std::vector<char>& buffer, size_t count, std::vector<double>& out) {
  for (size_t i = 0; i < count; ++i) {
    T v;
    std::memcpy(&v, buffer.data() + i * sizeof(T), sizeof(T));
    out.push_back(double(v));
  }
}

// The pixel module must describe monochrome integer or float samples GDCM can decode; its
// image reader asserts (aborts) on some impossible values instead of failing.
void checkPixelModule(const DicomSlice& s) {
  if (s.samplesPerPixel != 1)
    failLoad(s.file, "colour or bad SamplesPerPixel " + std::to_string(s.samplesPerPixel) +
                         " (monochrome images only)");
  const int64_t bits = s.bitsAllocated;
  if (bits != 8 && bits != 16 && bits != 32 && bits != 64)
    failLoad(s.file, "unsupported BitsAllocated " + std::to_string(bits) + " (8, 16, 32 or 64)");
  if (s.bitsStored < 1 || s.bitsStored > bits || s.highBit < s.bitsStored - 1 || s.highBit >= bits)
    failLoad(s.file, "inconsistent BitsStored " + std::to_string(s.bitsStored) + " and HighBit " +
                         std::to_string(s.highBit));
  if (!s.photometric.empty() && s.photometric != "MONOCHROME1" && s.photometric != "MONOCHROME2")
    failLoad(s.file, "PhotometricInterpretation " + quoteText(s.photometric, 20) +
                         " (monochrome images only)");
  if (s.representation != 0 && s.representation != 1)
    failLoad(s.file, "bad PixelRepresentation " + std::to_string(s.representation));
}

SlicePixels readSlice(const DicomSlice& slice) {
  checkPixelModule(slice);
  gdcm::ImageReader reader;
  reader.SetFileName(slice.file.c_str());
  if (!reader.Read()) failLoad(slice.file, "GDCM cannot read the image");
  const gdcm::Image& image = reader.GetImage();
  const unsigned* dims = image.GetDimensions();
  const gdcm::PixelFormat& format = image.GetPixelFormat();
  if (format.GetSamplesPerPixel() != 1)
    failLoad(slice.file, "colour DICOM images (" + std::to_string(format.GetSamplesPerPixel()) +
                             " samples per pixel) are not supported");
  if (int64_t(dims[0]) != slice.columns || int64_t(dims[1]) != slice.rows)
    failLoad(slice.file, "image size disagrees with Rows and Columns");
  const uint64_t count = uint64_t(dims[0]) * dims[1] *
                         uint64_t(std::max(1u, image.GetNumberOfDimensions() > 2 ? dims[2] : 1u));
  if (count != uint64_t(slice.rows) * uint64_t(slice.columns) * uint64_t(slice.frames))
    failLoad(slice.file, "pixel count disagrees with the header");
  // The stored pixel data must be able to hold the image before a buffer is sized by Rows and
  // Columns: all of it uncompressed; compressed, within a ratio no real image reaches.
  const uint64_t need = count * format.GetPixelSize();
  uint64_t capacity = 0;
  if (const gdcm::ByteValue* raw = image.GetDataElement().GetByteValue())
    capacity = raw->GetLength();
  else if (const gdcm::SequenceOfFragments* f = image.GetDataElement().GetSequenceOfFragments())
    capacity = uint64_t(f->ComputeByteLength()) * 65536 + (1u << 20);
  if (capacity < need)
    failLoad(slice.file, "pixel data cannot hold a " + std::to_string(slice.columns) + " x " +
                             std::to_string(slice.rows) + " image (truncated file?)");
  checkAllocation(slice.file, need, "DICOM image");
  std::vector<char> buffer(image.GetBufferLength());
  if (buffer.size() < count * format.GetPixelSize() || !image.GetBuffer(buffer.data()))
    failLoad(slice.file, "pixel data are missing, truncated or cannot be decoded");
  SlicePixels out;
  out.slope = image.GetSlope();
  out.intercept = image.GetIntercept();
  out.type = format.GetScalarType();
  out.values.reserve(size_t(count));
  switch (format.GetScalarType()) {
    case gdcm::PixelFormat::UINT8:
      appendValues<uint8_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::INT8:
      appendValues<int8_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::UINT16:
      appendValues<uint16_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::INT16:
      appendValues<int16_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::UINT32:
      appendValues<uint32_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::INT32:
      appendValues<int32_t>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::FLOAT32:
      appendValues<float>(buffer, count, out.values);
      break;
    case gdcm::PixelFormat::FLOAT64:
      appendValues<double>(buffer, count, out.values);
      break;
    default:
      failLoad(slice.file, std::string("unsupported pixel type ") + format.GetScalarTypeAsString());
  }
  if (!std::isfinite(out.slope) || !std::isfinite(out.intercept) || out.slope == 0.0)
    failLoad(slice.file, "bad RescaleSlope or RescaleIntercept");
  for (double& v : out.values) v = v * out.slope + out.intercept;
  return out;
}

// The narrowest volume type that holds every value exactly.
FileScalar fittingType(const std::vector<double>& values, bool integral) {
  if (!integral) return FileScalar::Float32;
  double lo = 0.0, hi = 0.0;
  if (!values.empty()) lo = hi = values[0];
  for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo >= 0 && hi <= 255) return FileScalar::UInt8;
  if (lo >= -32768 && hi <= 32767) return FileScalar::Int16;
  if (lo >= 0 && hi <= 65535) return FileScalar::UInt16;
  return FileScalar::Float32;
}

std::vector<uint8_t> encode(const std::vector<double>& values, FileScalar type) {
  std::vector<uint8_t> out(values.size() * fileScalarSize(type));
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t* p = out.data() + i * fileScalarSize(type);
    switch (type) {
      case FileScalar::UInt8:
        *p = uint8_t(values[i]);
        break;
      case FileScalar::Int16: {
        const auto v = int16_t(values[i]);
        std::memcpy(p, &v, 2);
        break;
      }
      case FileScalar::UInt16: {
        const auto v = uint16_t(values[i]);
        std::memcpy(p, &v, 2);
        break;
      }
      default: {
        const auto v = float(values[i]);
        std::memcpy(p, &v, 4);
        break;
      }
    }
  }
  return out;
}

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

// The folder of `file` relative to `root` (where a series lies in a CD's tree).
std::string relativeFolder(const std::string& file, const std::string& root) {
  const std::filesystem::path rel =
      std::filesystem::path(file).parent_path().lexically_relative(root);
  return rel.empty() ? std::string(".") : rel.generic_string();
}

}  // namespace

Volume loadDicom(const std::string& path, const std::string& seriesUid) {
  std::error_code ec;
  const std::filesystem::path named(path);
  // A CD's DICOMDIR names the images in the folders below it: opened as that folder is.
  const bool dicomdir = toLower(named.filename().string()) == "dicomdir";
  const bool folder = dicomdir || std::filesystem::is_directory(path, ec);
  std::string dir = std::filesystem::is_directory(path, ec) ? path : named.parent_path().string();
  if (dir.empty()) dir = ".";
  if (!folder && !looksLikeDicom(path))
    failLoad(path,
             "not a DICOM file (no 'DICM' at byte 128; files without the Part 10 preamble "
             "are not read)");
  std::string fileSeries;
  std::vector<DicomSeries> all = scanDicomFolder(dir, folder ? std::string() : path, &fileSeries);
  // No image in the folder itself: the images of the folders below it (a CD's tree).
  const bool below = folder && all.empty();
  if (below) all = scanDicomFolder(dir, std::string(), nullptr, true);
  if (all.empty())
    failLoad(path, folder ? "a directory with no DICOM image or TIFF file, in it or below it"
                          : "not a DICOM image");
  if (!folder && fileSeries.empty() && seriesUid.empty())
    failLoad(path, "not a DICOM image (no Rows and Columns)");
  const DicomSeries& chosen = pickSeries(path, all, seriesUid, fileSeries);

  VolumeLayout layout;
  layout.patientFrame = true;
  if (all.size() > 1 || below)  // below: where the series lies, even alone
    for (const DicomSeries& s : all)
      layout.notes.push_back(
          "series " + s.uid + ": " + std::to_string(s.slices.size()) + " slices" +
          (s.description.empty() ? "" : ", " + s.description) +
          (below ? " in " + quoteText(relativeFolder(s.slices.front().file, dir), 80) : "") +
          (&s == &chosen ? " (open)" : " (--series UID opens it)"));
  std::vector<DicomSlice> slices = chosen.slices;
  // The size most slices have is the series' size; the odd one out is named.
  std::map<std::pair<int64_t, int64_t>, size_t> sizes;
  for (const DicomSlice& s : slices) sizes[{s.columns, s.rows}]++;
  const auto common =
      std::max_element(sizes.begin(), sizes.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->first;
  for (const DicomSlice& s : slices) {
    if (s.columns != common.first || s.rows != common.second)
      failLoad(s.file, "slice of " + std::to_string(s.columns) + " x " + std::to_string(s.rows) +
                           " in a series of " + std::to_string(common.first) + " x " +
                           std::to_string(common.second));
    if (s.frames != 1 && slices.size() > 1)
      failLoad(s.file, "a multi-frame file inside a series of several files");
  }
  const glm::dvec3 step = sortDicomSlices(path, slices, layout.notes);
  const DicomSlice& base = slices.front();
  layout.dims = {base.columns, base.rows, int64_t(slices.size()) * base.frames};
  if (!base.hasSpacing) layout.notes.push_back("no PixelSpacing: 1 assumed");
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
  const uint64_t total = dataByteCount(path, layout.dims, FileScalar::Float32);
  checkAllocation(path, total * 2, "DICOM values");  // doubles while rescaling

  std::vector<double> values;
  bool integral = true, sameRescale = true, sameType = true;
  double slope0 = 0.0, intercept0 = 0.0;
  gdcm::PixelFormat::ScalarType type0 = gdcm::PixelFormat::UNKNOWN;
  for (size_t i = 0; i < slices.size(); ++i) {
    const SlicePixels px = readSlice(slices[i]);
    const bool intType =
        px.type != gdcm::PixelFormat::FLOAT32 && px.type != gdcm::PixelFormat::FLOAT64;
    integral = integral && intType && px.slope == std::round(px.slope) &&
               px.intercept == std::round(px.intercept);
    if (i == 0) slope0 = px.slope, intercept0 = px.intercept, type0 = px.type;
    sameType = sameType && px.type == type0;
    sameRescale = sameRescale && px.slope == slope0 && px.intercept == intercept0;
    values.insert(values.end(), px.values.begin(), px.values.end());
  }
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
  return makeVolume(path, layout, encode(values, layout.type));
}

}  // namespace ewa

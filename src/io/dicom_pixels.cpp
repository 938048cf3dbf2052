// DICOM pixels through GDCM: the pixel module checked, every frame decoded and rescaled.
#include "io/dicom_pixels.h"

#include <gdcmImageHelper.h>
#include <gdcmMediaStorage.h>
#include <gdcmPixmap.h>
#include <gdcmPixmapReader.h>
#include <gdcmSequenceOfFragments.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "io/dicom_colour.h"
#include "io/dicom_items.h"
#include "io/file_bytes.h"
#include "io/jpeg_header_check.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

namespace {

// Where the samples of one channel lie in a decoded buffer: every `samples`-th from `channel`
// (colour-by-pixel), or the channel's plane in each frame (colour-by-plane, PlanarConfiguration
// 1).
struct ChannelLayout {
  size_t samples = 1, channel = 0, plane = 1;
  bool planar = false;
  size_t index(size_t pixel) const {
    if (!planar) return pixel * samples + channel;
    return (pixel / plane) * plane * samples + channel * plane + pixel % plane;
  }
};

template <typename T>
void appendValues(const std::vector<char>& buffer, size_t count, const ChannelLayout& layout,
                  std::vector<double>& out) {
  for (size_t i = 0; i < count; ++i) {
    T v;
    std::memcpy(&v, buffer.data() + layout.index(i) * sizeof(T), sizeof(T));
    out.push_back(double(v));
  }
}

// The pixel module must describe monochrome (or colour) integer or float samples GDCM can
// decode; its image reader asserts (aborts) on some impossible values instead of failing.
void checkPixelModule(const DicomSlice& s) {
  const bool colour = s.samplesPerPixel == 3;
  if (s.samplesPerPixel != 1 && !colour)
    failLoad(s.file,
             "bad SamplesPerPixel " + std::to_string(s.samplesPerPixel) + " (1, or 3 for colour)");
  const int64_t bits = s.bitsAllocated;
  if (bits != 8 && bits != 16 && bits != 32 && bits != 64)
    failLoad(s.file, "unsupported BitsAllocated " + std::to_string(bits) + " (8, 16, 32 or 64)");
  if (s.bitsStored < 1 || s.bitsStored > bits || s.highBit < s.bitsStored - 1 || s.highBit >= bits)
    failLoad(s.file, "inconsistent BitsStored " + std::to_string(s.bitsStored) + " and HighBit " +
                         std::to_string(s.highBit));
  // GDCM's raw decoder asserts on 8 bits allocated with fewer stored (found by fuzzing).
  if (bits == 8 && s.bitsStored != 8)
    failLoad(s.file, "BitsStored " + std::to_string(s.bitsStored) +
                         " with BitsAllocated 8 is not read (8 bits stored only)");
  const bool mono =
      s.photometric.empty() || s.photometric == "MONOCHROME1" || s.photometric == "MONOCHROME2";
  if (colour ? !isColourSpace(s.photometric) : !mono)
    failLoad(s.file, "PhotometricInterpretation " + quoteText(s.photometric, 20) + " with " +
                         std::to_string(s.samplesPerPixel) +
                         " samples a pixel (MONOCHROME1 or MONOCHROME2 with 1; RGB, YBR_FULL, "
                         "YBR_FULL_422, YBR_RCT or YBR_ICT with 3)");
  if (s.representation != 0 && s.representation != 1)
    failLoad(s.file, "bad PixelRepresentation " + std::to_string(s.representation));
  if (isYbrFull(s.photometric) && (s.representation != 0 || s.bitsAllocated > 16))
    failLoad(s.file, "PhotometricInterpretation " + quoteText(s.photometric, 20) +
                         " with signed or wider than 16-bit samples is not read");
  // GDCM's pixmap reader asserts on any other value (even for one sample a pixel).
  if (s.planarConfiguration != 0 && s.planarConfiguration != 1)
    failLoad(s.file, "bad PlanarConfiguration" +
                         (s.planarConfiguration < 0 ? std::string(" (not a number)")
                                                    : " " + std::to_string(s.planarConfiguration)) +
                         " (0 or 1)");
}

// The classes whose rescale GDCM takes from the functional groups (its ImageHelper).
bool functionalGroupsRescale(const gdcm::MediaStorage& ms) {
  using M = gdcm::MediaStorage;
  for (const M::MSType type :
       {M::EnhancedCTImageStorage, M::EnhancedMRImageStorage, M::EnhancedPETImageStorage,
        M::XRay3DAngiographicImageStorage, M::XRay3DCraniofacialImageStorage,
        M::SegmentationStorage, M::BreastTomosynthesisImageStorage,
        M::BreastProjectionXRayImageStorageForPresentation,
        M::BreastProjectionXRayImageStorageForProcessing, M::LegacyConvertedEnhancedMRImageStorage,
        M::LegacyConvertedEnhancedCTImageStorage, M::LegacyConvertedEnhancedPETImageStorage})
    if (ms == type) return true;
  return false;
}

// (intercept, slope) as GDCM's image reader gives them; for the enhanced classes, from the
// Pixel Value Transformation of the shared functional groups, else the first frame's, read here
// (GDCM's own reading asserts on malformed sequences).
std::vector<double> rescaleOf(const gdcm::File& file, const std::string& path) {
  gdcm::MediaStorage ms;
  ms.SetFromFile(file);
  const gdcm::DataSet& ds = file.GetDataSet();
  if (!functionalGroupsRescale(ms)) {
    // GDCM's helper asserts when it reads a slope of 0 (found by fuzzing, with an intercept of
    // "S0"): each, where present, must be one finite number, the slope other than 0.
    for (const auto& [tag, name] : {std::pair{gdcm::Tag(0x0028, 0x1052), "RescaleIntercept"},
                                    std::pair{gdcm::Tag(0x0028, 0x1053), "RescaleSlope"}}) {
      if (!ds.FindDataElement(tag) || ds.GetDataElement(tag).IsEmpty()) continue;
      const std::vector<double> v = dicomElementNumbers(&ds, tag);
      if (v.size() != 1 || !std::isfinite(v[0]) || (tag.GetElement() == 0x1053 && v[0] == 0.0))
        failLoad(path, std::string("bad ") + name + " (one number" +
                           (tag.GetElement() == 0x1053 ? ", not 0)" : ")"));
    }
    return gdcm::ImageHelper::GetRescaleInterceptSlopeValue(file);
  }
  const gdcm::Tag transformation(0x0028, 0x9145);
  DicomItems items;
  for (const gdcm::Tag& groups : {kSharedFunctionalGroups, kPerFrameFunctionalGroups}) {
    const gdcm::DataSet* item = items.first(items.first(&ds, groups), transformation);
    const std::vector<double> intercept = dicomElementNumbers(item, gdcm::Tag(0x0028, 0x1052));
    const std::vector<double> slope = dicomElementNumbers(item, gdcm::Tag(0x0028, 0x1053));
    if (intercept.size() == 1 && slope.size() == 1)
      return {intercept[0], slope[0] == 0.0 ? 1.0 : slope[0]};
  }
  return {0.0, 1.0};
}

// Appends one channel's samples (as `layout` places them) of `buffer`'s pixel type.
void appendChannel(const std::vector<char>& buffer, size_t count, const ChannelLayout& layout,
                   const gdcm::PixelFormat& format, const std::string& file,
                   std::vector<double>& out) {
  switch (format.GetScalarType()) {
    case gdcm::PixelFormat::UINT8:
      return appendValues<uint8_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::INT8:
      return appendValues<int8_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::UINT16:
      return appendValues<uint16_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::INT16:
      return appendValues<int16_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::UINT32:
      return appendValues<uint32_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::INT32:
      return appendValues<int32_t>(buffer, count, layout, out);
    case gdcm::PixelFormat::FLOAT32:
      return appendValues<float>(buffer, count, layout, out);
    case gdcm::PixelFormat::FLOAT64:
      return appendValues<double>(buffer, count, layout, out);
    default:
      failLoad(file, std::string("unsupported pixel type ") + format.GetScalarTypeAsString());
  }
}

}  // namespace

SlicePixels readSlice(const DicomSlice& slice, int channel) {
  checkPixelModule(slice);
  // The pixmap reader decodes without GDCM's geometry (ImageReader's spacing, origin and
  // direction code asserts on malformed functional groups; the geometry is ours anyway).
  gdcm::PixmapReader reader;
  reader.SetFileName(slice.file.c_str());
  if (!reader.Read()) failLoad(slice.file, "GDCM cannot read the image");
  const gdcm::Pixmap& image = reader.GetPixmap();
  checkColourCoding(slice, image.GetTransferSyntax());
  const unsigned* dims = image.GetDimensions();
  const gdcm::PixelFormat& format = image.GetPixelFormat();
  const int samples = format.GetSamplesPerPixel();
  if (samples != slice.samplesPerPixel)
    failLoad(slice.file, "SamplesPerPixel disagrees with the pixel data");
  checkChannel(slice.file, channel, samples);
  if (int64_t(dims[0]) != slice.columns || int64_t(dims[1]) != slice.rows)
    failLoad(slice.file, "image size disagrees with Rows and Columns");
  const uint64_t count = uint64_t(dims[0]) * dims[1] *
                         uint64_t(std::max(1u, image.GetNumberOfDimensions() > 2 ? dims[2] : 1u));
  if (count != uint64_t(slice.rows) * uint64_t(slice.columns) * uint64_t(slice.frames))
    failLoad(slice.file, "pixel count disagrees with the header");
  // Uncompressed 4:2:2 chroma is two bytes a pixel, which GDCM's raw decoder does not expand:
  // read here (rgbOfYbr422).
  const bool raw422 =
      slice.photometric == "YBR_FULL_422" && !image.GetTransferSyntax().IsEncapsulated();
  if (raw422 && format.GetBitsAllocated() != 8)
    failLoad(slice.file, "uncompressed YBR_FULL_422 of " +
                             std::to_string(format.GetBitsAllocated()) +
                             " bits is not read (8 only)");
  // The stored pixel data must be able to hold the image before a buffer is sized by Rows and
  // Columns: all of it uncompressed; compressed, within a ratio no real image reaches.
  const uint64_t need = count * (raw422 ? 2 : format.GetPixelSize());
  uint64_t capacity = 0;
  if (const gdcm::ByteValue* raw = image.GetDataElement().GetByteValue())
    capacity = raw->GetLength();
  else if (const gdcm::SequenceOfFragments* f = image.GetDataElement().GetSequenceOfFragments())
    capacity = uint64_t(f->ComputeByteLength()) * 65536 + (1u << 20);
  if (capacity < need)
    failLoad(slice.file, "pixel data cannot hold a " + std::to_string(slice.columns) + " x " +
                             std::to_string(slice.rows) + " image (truncated file?)");
  checkAllocation(slice.file, need, "DICOM image");
  std::vector<char> buffer;
  if (!raw422) {
    buffer.resize(image.GetBufferLength());
    if (buffer.size() < count * format.GetPixelSize() || !image.GetBuffer(buffer.data()))
      failLoad(slice.file, "pixel data are missing, truncated or cannot be decoded");
  }
  SlicePixels out;
  const std::vector<double> rescale = rescaleOf(reader.GetFile(), slice.file);
  out.intercept = rescale[0];
  out.slope = rescale[1];
  out.type = format.GetScalarType();
  out.values.reserve(size_t(count));
  ChannelLayout layout;
  layout.samples = size_t(samples);
  layout.channel = size_t(channel);
  layout.plane = size_t(dims[0]) * dims[1];
  layout.planar = samples > 1 && image.GetPlanarConfiguration() == 1;
  if (raw422) {
    const gdcm::ByteValue* raw = image.GetDataElement().GetByteValue();
    out.values = rgbOfYbr422(slice.file, reinterpret_cast<const uint8_t*>(raw->GetPointer()),
                             raw->GetLength(), slice.columns, count, channel);
  } else if (isYbrFull(slice.photometric)) {
    // Y, Cb and Cr (GDCM's JPEG decoder returns YBR_FULL_422 upsampled, unconverted) to RGB.
    std::vector<double> ybr[3];
    for (int c = 0; c < 3; ++c) {
      layout.channel = size_t(c);
      ybr[c].reserve(size_t(count));
      appendChannel(buffer, count, layout, format, slice.file, ybr[c]);
    }
    for (size_t i = 0; i < size_t(count); ++i)
      out.values.push_back(
          rgbOfYbr(ybr[0][i], ybr[1][i], ybr[2][i], channel, format.GetBitsStored()));
  } else {
    appendChannel(buffer, count, layout, format, slice.file, out.values);
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

}  // namespace ewa

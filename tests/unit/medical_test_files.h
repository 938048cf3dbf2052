// Writers for hand-made NIfTI, DICOM and TIFF test files (GDCM and libtiff write the latter two).
#pragma once

#include <gdcmAttribute.h>
#include <gdcmImageChangeTransferSyntax.h>
#include <gdcmImageReader.h>
#include <gdcmImageWriter.h>
#include <gdcmReader.h>
#include <gdcmSequenceOfItems.h>
#include <gdcmTrace.h>
#include <gdcmWriter.h>
#include <tiffio.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "loader_test_files.h"

namespace ewa::testing {

// A NIfTI-1 single-file header (348 bytes, "n+1", 4 extension bytes) in the given byte order.
struct NiftiFields {
  std::array<int16_t, 8> dim{3, 2, 3, 4, 1, 1, 1, 1};
  int16_t datatype = 2, bitpix = 8;
  std::array<float, 8> pixdim{1, 1, 1, 1, 0, 0, 0, 0};
  float voxOffset = 352, sclSlope = 0, sclInter = 0;
  int16_t qformCode = 0, sformCode = 0;
  uint8_t xyztUnits = 0;
  std::array<float, 12> srow{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
};

inline std::string niftiHeader(const NiftiFields& f, bool bigEndian = false) {
  std::string h(352, '\0');
  auto put = [&](size_t at, const std::string& bytes) { h.replace(at, bytes.size(), bytes); };
  put(0, uintBytes(348, 4, bigEndian));
  for (int i = 0; i < 8; ++i)
    put(40 + 2 * size_t(i), uintBytes(uint16_t(f.dim[size_t(i)]), 2, bigEndian));
  put(70, uintBytes(uint16_t(f.datatype), 2, bigEndian));
  put(72, uintBytes(uint16_t(f.bitpix), 2, bigEndian));
  auto putFloat = [&](size_t at, float v) {
    uint32_t u;
    std::memcpy(&u, &v, 4);
    put(at, uintBytes(u, 4, bigEndian));
  };
  for (int i = 0; i < 8; ++i) putFloat(76 + 4 * size_t(i), f.pixdim[size_t(i)]);
  putFloat(108, f.voxOffset);
  putFloat(112, f.sclSlope);
  putFloat(116, f.sclInter);
  h[123] = char(f.xyztUnits);
  put(252, uintBytes(uint16_t(f.qformCode), 2, bigEndian));
  put(254, uintBytes(uint16_t(f.sformCode), 2, bigEndian));
  for (int i = 0; i < 12; ++i) putFloat(280 + 4 * size_t(i), f.srow[size_t(i)]);
  put(344, std::string("n+1\0", 4));
  return h;
}

// Reads the DICOM file `from`, lets `edit` change its dataset and writes it to `to` (by
// default back to `from`): how the tests patch what GDCM's image writer will not write.
inline bool editDicom(const std::string& from, const std::function<void(gdcm::DataSet&)>& edit,
                      const std::string& to = "") {
  gdcm::Reader reader;
  reader.SetFileName(from.c_str());
  if (!reader.Read()) return false;
  edit(reader.GetFile().GetDataSet());
  gdcm::Writer writer;
  writer.SetFile(reader.GetFile());
  writer.SetFileName((to.empty() ? from : to).c_str());
  return writer.Write();
}

// One CT slice written by GDCM: int16 pixels `values` (rows * columns), at `position` with
// the given orientation, pixel spacing and rescale, in series `seriesUid`.
struct DicomSliceSpec {
  std::string seriesUid = "1.2.826.0.1.3680043.2.1125.1";
  unsigned rows = 4, columns = 5;
  std::array<double, 3> position{0, 0, 0};
  std::array<double, 6> orientation{1, 0, 0, 0, 1, 0};
  double rowSpacing = 0.5, columnSpacing = 0.75;
  double slope = 1.0, intercept = 0.0;
  std::vector<int16_t> values;  // empty: i + 10 * j + 100 * slice index given by position z
  // RGB instead: uint8 samples 40 c + i + 5 j + 20 z for channel c, by pixel or by plane.
  bool rgb = false, planar = false;
};

// The sample of channel `c` at column i, row j of an RGB test slice at position z.
inline int rgbTestSample(int c, int i, int j, int z) {
  return 40 * c + i + 5 * j + 20 * z;
}

inline bool writeDicomSlice(const std::string& path, const DicomSliceSpec& s) {
  gdcm::Trace::WarningOff();  // GDCM's notes on the test's own files (a default photometric)
  gdcm::ImageWriter writer;
  gdcm::Image& image = writer.GetImage();
  image.SetNumberOfDimensions(2);
  image.SetDimension(0, s.columns);
  image.SetDimension(1, s.rows);
  image.SetOrigin(s.position.data());
  image.SetDirectionCosines(s.orientation.data());
  image.SetSpacing(0, s.columnSpacing);
  image.SetSpacing(1, s.rowSpacing);
  gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
  if (s.rgb) {
    image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::RGB);
    image.SetPixelFormat(gdcm::PixelFormat(3, 8, 8, 7, 0));
    image.SetPlanarConfiguration(s.planar ? 1 : 0);
    std::vector<uint8_t> samples;
    const int z = int(s.position[2]);
    for (int c = 0; c < (s.planar ? 3 : 1); ++c)
      for (unsigned j = 0; j < s.rows; ++j)
        for (unsigned i = 0; i < s.columns; ++i)
          for (int k = 0; k < (s.planar ? 1 : 3); ++k)
            samples.push_back(uint8_t(rgbTestSample(s.planar ? c : k, int(i), int(j), z)));
    pixels.SetByteValue(reinterpret_cast<const char*>(samples.data()), uint32_t(samples.size()));
  } else {
    image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::MONOCHROME2);
    image.SetPixelFormat(gdcm::PixelFormat::INT16);
    image.SetSlope(s.slope);
    image.SetIntercept(s.intercept);
    std::vector<int16_t> values = s.values;
    if (values.empty()) {
      for (unsigned j = 0; j < s.rows; ++j)
        for (unsigned i = 0; i < s.columns; ++i)
          values.push_back(int16_t(i + 10 * j + 100 * int(s.position[2])));
    }
    pixels.SetByteValue(reinterpret_cast<const char*>(values.data()),
                        uint32_t(values.size() * sizeof(int16_t)));
  }
  image.SetDataElement(pixels);
  gdcm::File& file = writer.GetFile();
  gdcm::DataSet& ds = file.GetDataSet();
  gdcm::Attribute<0x0008, 0x0016> sopClass;
  sopClass.SetValue("1.2.840.10008.5.1.4.1.1.2");  // CT Image Storage: keeps IPP and IOP
  ds.Replace(sopClass.GetAsDataElement());
  gdcm::Attribute<0x0008, 0x0060> modality;
  modality.SetValue("CT");
  ds.Replace(modality.GetAsDataElement());
  gdcm::Attribute<0x0020, 0x000e> series;
  series.SetValue(s.seriesUid);
  ds.Replace(series.GetAsDataElement());
  writer.SetFileName(path.c_str());
  if (!writer.Write()) return false;
  // The image writer keeps only x and y of a 2D image's origin: set the position afterwards.
  return editDicom(path, [&](gdcm::DataSet& ds) {
    gdcm::Attribute<0x0020, 0x0032> ipp;
    ipp.SetValues(s.position.data(), 3);
    ds.Replace(ipp.GetAsDataElement());
  });
}

// A folder of `count` slices 2 apart along z, in shuffled file names.
inline std::string dicomSeries(const TempDir& dir, const std::string& name, int count,
                               DicomSliceSpec spec = {}) {
  std::filesystem::create_directories(dir.path(name));
  for (int n = 0; n < count; ++n) {
    spec.position = {10.0, 20.0, 2.0 * ((n * 7) % count)};
    EXPECT_TRUE(writeDicomSlice(dir.path(name + "/im" + std::to_string(n) + ".dcm"), spec));
  }
  return dir.path(name);
}

// A volume's notes, one a line (to search for one).
inline std::string allNotes(const Volume& v) {
  std::string notes;
  for (const std::string& n : v.notes()) notes += n + "\n";
  return notes;
}

// An enhanced CT file of one frame a plane at each z of `frameZ` (in that stored order), int16
// pixels i + 10 * j + 100 * z, its geometry only in the functional groups: Pixel Measures and
// Plane Orientation shared, a Plane Position a frame (`perFrameItems` of them: fewer makes a
// file whose groups do not cover its frames), the rescale in the shared Pixel Value
// Transformation.
struct EnhancedDicomSpec {
  unsigned rows = 4, columns = 5;
  std::vector<double> frameZ{0.0, 2.0};
  int perFrameItems = -1;  // -1: one a frame
  double rowSpacing = 0.5, columnSpacing = 0.75;
  double slope = 1.0, intercept = 0.0;  // in the shared Pixel Value Transformation
};

// A sequence element of `tag` with one item a dataset of `items`.
inline gdcm::DataElement sequenceOf(const gdcm::Tag& tag, const std::vector<gdcm::DataSet>& items) {
  gdcm::SmartPointer<gdcm::SequenceOfItems> sq = new gdcm::SequenceOfItems;
  sq->SetLengthToUndefined();
  for (const gdcm::DataSet& ds : items) {
    gdcm::Item item;
    item.SetVLToUndefined();
    item.SetNestedDataSet(ds);
    sq->AddItem(item);
  }
  gdcm::DataElement de(tag);
  de.SetVR(gdcm::VR::SQ);
  de.SetValue(*sq);
  de.SetVLToUndefined();
  return de;
}

inline bool writeEnhancedDicom(const std::string& path, const EnhancedDicomSpec& s) {
  const auto frames = unsigned(s.frameZ.size());
  gdcm::ImageWriter writer;
  gdcm::Image& image = writer.GetImage();
  image.SetNumberOfDimensions(3);
  image.SetDimension(0, s.columns);
  image.SetDimension(1, s.rows);
  image.SetDimension(2, frames);
  image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::MONOCHROME2);
  image.SetPixelFormat(gdcm::PixelFormat::INT16);
  std::vector<int16_t> values;
  for (double z : s.frameZ)
    for (unsigned j = 0; j < s.rows; ++j)
      for (unsigned i = 0; i < s.columns; ++i) values.push_back(int16_t(i + 10 * j + 100 * int(z)));
  gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
  pixels.SetByteValue(reinterpret_cast<const char*>(values.data()),
                      uint32_t(values.size() * sizeof(int16_t)));
  image.SetDataElement(pixels);
  gdcm::DataSet& top = writer.GetFile().GetDataSet();
  gdcm::Attribute<0x0008, 0x0016> sopClass;
  sopClass.SetValue("1.2.840.10008.5.1.4.1.1.2");
  top.Replace(sopClass.GetAsDataElement());
  writer.SetFileName(path.c_str());
  if (!writer.Write()) return false;
  // Then the geometry moved into the functional groups, as enhanced files hold it.
  return editDicom(path, [&](gdcm::DataSet& ds) {
    for (const gdcm::Tag& t :
         {gdcm::Tag(0x0020, 0x0032), gdcm::Tag(0x0020, 0x0037), gdcm::Tag(0x0028, 0x0030),
          gdcm::Tag(0x5200, 0x9229), gdcm::Tag(0x5200, 0x9230)})
      ds.Remove(t);
    gdcm::Attribute<0x0008, 0x0016> enhanced;
    enhanced.SetValue("1.2.840.10008.5.1.4.1.1.2.1");  // Enhanced CT Image Storage
    ds.Replace(enhanced.GetAsDataElement());
    gdcm::DataSet measures, orientation, shared;
    gdcm::Attribute<0x0028, 0x0030> spacing;
    const double sp[2] = {s.rowSpacing, s.columnSpacing};
    spacing.SetValues(sp, 2);
    measures.Insert(spacing.GetAsDataElement());
    gdcm::Attribute<0x0020, 0x0037> iop;
    const double cosines[6] = {1, 0, 0, 0, 1, 0};
    iop.SetValues(cosines, 6);
    orientation.Insert(iop.GetAsDataElement());
    shared.Insert(sequenceOf(gdcm::Tag(0x0028, 0x9110), {measures}));
    shared.Insert(sequenceOf(gdcm::Tag(0x0020, 0x9116), {orientation}));
    gdcm::DataSet transformation;
    gdcm::Attribute<0x0028, 0x1052> intercept;
    intercept.SetValue(s.intercept);
    transformation.Insert(intercept.GetAsDataElement());
    gdcm::Attribute<0x0028, 0x1053> slope;
    slope.SetValue(s.slope);
    transformation.Insert(slope.GetAsDataElement());
    shared.Insert(sequenceOf(gdcm::Tag(0x0028, 0x9145), {transformation}));
    ds.Insert(sequenceOf(gdcm::Tag(0x5200, 0x9229), {shared}));
    std::vector<gdcm::DataSet> perFrame;
    const int items = s.perFrameItems < 0 ? int(frames) : s.perFrameItems;
    for (int f = 0; f < items; ++f) {
      gdcm::DataSet position, item;
      gdcm::Attribute<0x0020, 0x0032> ipp;
      const double p[3] = {10.0, 20.0, s.frameZ[size_t(f) % frames]};
      ipp.SetValues(p, 3);
      position.Insert(ipp.GetAsDataElement());
      item.Insert(sequenceOf(gdcm::Tag(0x0020, 0x9113), {position}));
      perFrame.push_back(item);
    }
    ds.Insert(sequenceOf(gdcm::Tag(0x5200, 0x9230), perFrame));
  });
}

// Rewrites the DICOM file at `path` in another transfer syntax (RLE or JPEG lossless, ...).
inline bool recompressDicom(const std::string& path, gdcm::TransferSyntax::TSType syntax) {
  gdcm::ImageReader reader;
  reader.SetFileName(path.c_str());
  if (!reader.Read()) return false;
  gdcm::ImageChangeTransferSyntax change;
  change.SetTransferSyntax(syntax);
  change.SetInput(reader.GetImage());
  if (!change.Change()) return false;
  gdcm::ImageWriter writer;
  writer.SetFile(reader.GetFile());
  writer.SetImage(change.GetOutput());
  writer.SetFileName(path.c_str());
  return writer.Write();
}

// The data set of the Part 10 file at `path` without its preamble and meta header (group 0002,
// explicit VR little-endian as the standard has it): a bare data set, as ACR-NEMA files hold.
inline std::string bareDataSet(const std::string& path) {
  const std::string b = fileBytes(path);
  if (b.size() < 132 || b.compare(128, 4, "DICM") != 0) return {};
  size_t p = 132;
  while (p + 12 <= b.size() && b[p] == 2 && b[p + 1] == 0) {
    const std::string vr = b.substr(p + 4, 2);
    const bool longForm = vr == "OB" || vr == "OW" || vr == "UN" || vr == "SQ" || vr == "UT";
    const auto at = [&](size_t i) { return uint64_t(uint8_t(b[i])); };
    p += longForm ? 12 + size_t(at(p + 8) | at(p + 9) << 8 | at(p + 10) << 16 | at(p + 11) << 24)
                  : 8 + size_t(at(p + 6) | at(p + 7) << 8);
  }
  return b.substr(p);
}

// A TIFF written by libtiff: one page per entry of `pages` (width x height samples of T each,
// `samples` per pixel interleaved), with an optional ImageDescription on the first page.
template <typename T>
bool writeTiff(const std::string& path, uint32_t width, uint32_t height,
               const std::vector<std::vector<T>>& pages, uint16_t sampleFormat,
               uint16_t samples = 1, const std::string& description = "") {
  TIFF* t = TIFFOpen(path.c_str(), "w");
  if (!t) return false;
  for (size_t p = 0; p < pages.size(); ++p) {
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, width);
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, height);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(8 * sizeof(T)));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, samples);
    TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, sampleFormat);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, samples == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, height);
    if (p == 0 && !description.empty())
      TIFFSetField(t, TIFFTAG_IMAGEDESCRIPTION, description.c_str());
    TIFFSetField(t, TIFFTAG_XRESOLUTION, description.empty() ? 72.0f : 4.0f);  // ImageJ: 0.25
    TIFFSetField(t, TIFFTAG_YRESOLUTION, description.empty() ? 72.0f : 2.0f);  // ImageJ: 0.5
    TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, description.empty() ? RESUNIT_INCH : RESUNIT_NONE);
    std::vector<T> row(size_t(width) * samples);
    for (uint32_t y = 0; y < height; ++y) {
      std::memcpy(row.data(), pages[p].data() + size_t(y) * width * samples,
                  row.size() * sizeof(T));
      if (TIFFWriteScanline(t, row.data(), y, 0) < 0) {
        TIFFClose(t);
        return false;
      }
    }
    TIFFWriteDirectory(t);
  }
  TIFFClose(t);
  return true;
}

// The same stored in tiles of `tile` x `tile` pixels (pixels past the page's edge zero), the
// samples interleaved or in separate planes (`planar`), compressed with `compression`.
template <typename T>
bool writeTiledTiff(const std::string& path, uint32_t width, uint32_t height,
                    const std::vector<std::vector<T>>& pages, uint16_t sampleFormat,
                    uint16_t samples, uint32_t tile, bool planar,
                    uint16_t compression = COMPRESSION_NONE) {
  TIFF* t = TIFFOpen(path.c_str(), "w");
  if (!t) return false;
  bool ok = true;
  for (size_t p = 0; p < pages.size() && ok; ++p) {
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, width);
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, height);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(8 * sizeof(T)));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, samples);
    TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, sampleFormat);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, planar ? PLANARCONFIG_SEPARATE : PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_COMPRESSION, compression);
    TIFFSetField(t, TIFFTAG_TILEWIDTH, tile);
    TIFFSetField(t, TIFFTAG_TILELENGTH, tile);
    const uint32_t stride = planar ? 1 : samples;
    std::vector<T> block(size_t(tile) * tile * stride);
    for (uint16_t plane = 0; plane < (planar ? samples : 1); ++plane)
      for (uint32_t y0 = 0; y0 < height; y0 += tile)
        for (uint32_t x0 = 0; x0 < width; x0 += tile) {
          std::fill(block.begin(), block.end(), T(0));
          for (uint32_t y = y0; y < std::min(height, y0 + tile); ++y)
            for (uint32_t x = x0; x < std::min(width, x0 + tile); ++x)
              for (uint32_t c = 0; c < stride; ++c)
                block[(size_t(y - y0) * tile + (x - x0)) * stride + c] =
                    pages[p][(size_t(y) * width + x) * samples + (planar ? plane : c)];
          ok = ok && TIFFWriteTile(t, block.data(), x0, y0, 0, plane) >= 0;
        }
    ok = ok && TIFFWriteDirectory(t);
  }
  TIFFClose(t);
  return ok;
}

}  // namespace ewa::testing

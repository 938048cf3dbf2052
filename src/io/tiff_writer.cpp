// Encoding a volume as an OME-TIFF stack through libtiff, into memory (TIFFClientOpenExt).
#include "io/tiff_writer.h"

#include <tiffio.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "io/byte_order.h"
#include "io/text_numbers.h"
#include "io/tiff_pages.h"

namespace ewa {

namespace {

// The file being written: libtiff seeks back to patch offsets, so writes land anywhere.
struct MemoryFile {
  std::string bytes;
  uint64_t at = 0;
  std::string error;  // libtiff's first complaint
};

MemoryFile& fileOf(thandle_t h) {
  return *static_cast<MemoryFile*>(h);
}

tmsize_t readBytes(thandle_t h, void* out, tmsize_t n) {
  MemoryFile& f = fileOf(h);
  const uint64_t left = f.at < f.bytes.size() ? f.bytes.size() - f.at : 0;
  const auto count = tmsize_t(std::min<uint64_t>(uint64_t(n), left));
  if (count > 0) std::memcpy(out, f.bytes.data() + f.at, size_t(count));
  f.at += uint64_t(count);
  return count;
}

tmsize_t writeBytes(thandle_t h, void* in, tmsize_t n) {
  MemoryFile& f = fileOf(h);
  if (n <= 0) return 0;
  if (f.at + uint64_t(n) > f.bytes.size()) f.bytes.resize(size_t(f.at + uint64_t(n)));
  std::memcpy(f.bytes.data() + f.at, in, size_t(n));
  f.at += uint64_t(n);
  return n;
}

toff_t seekTo(thandle_t h, toff_t offset, int whence) {
  MemoryFile& f = fileOf(h);
  const uint64_t base = whence == SEEK_CUR ? f.at : whence == SEEK_END ? f.bytes.size() : 0;
  f.at = base + offset;
  return f.at;
}

int closeFile(thandle_t) {
  return 0;
}

toff_t sizeOf(thandle_t h) {
  return fileOf(h).bytes.size();
}

int noMap(thandle_t, tdata_t*, toff_t*) {
  return 0;
}

void noUnmap(thandle_t, tdata_t, toff_t) {}

// The volume's unit as OME names it (the same symbols) and its count in a centimetre.
struct OmeUnit {
  const char* symbol;
  double perCentimetre;
};

const OmeUnit* omeUnit(const std::string& unit) {
  static const OmeUnit kUnits[] = {{"m", 0.01}, {"cm", 1.0},  {"mm", 10.0},     {"\xC2\xB5m", 1e4},
                                   {"nm", 1e7}, {"pm", 1e10}, {"\xC3\x85", 1e8}};  // µm, Å
  for (const OmeUnit& u : kUnits)
    if (unit == u.symbol) return &u;
  return nullptr;
}

std::string escapeXml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else if (static_cast<unsigned char>(c) >= 0x20)
      out += c;
  }
  return out;
}

// OME's pixel types are scalarName's but for "float".
const char* omeType(ScalarType type) {
  return type == ScalarType::Float32 ? "float" : scalarName(type);
}

std::string omeXml(const Volume& v, const std::string& name) {
  const OmeUnit* unit = omeUnit(v.unit());
  const std::string u = unit ? unit->symbol : "reference frame";
  const auto& n = v.dims();
  const glm::dvec3& s = v.spacing();
  std::string x =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<OME xmlns=\"http://www.openmicroscopy.org/Schemas/OME/2016-06\" "
      "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
      "xsi:schemaLocation=\"http://www.openmicroscopy.org/Schemas/OME/2016-06 "
      "http://www.openmicroscopy.org/Schemas/OME/2016-06/ome.xsd\" Creator=\"ewaview\">";
  x += "<Image ID=\"Image:0\" Name=\"" + escapeXml(name) + "\">";
  x += "<Pixels ID=\"Pixels:0\" DimensionOrder=\"XYZCT\" Type=\"" + std::string(omeType(v.type())) +
       "\" SizeX=\"" + std::to_string(n[0]) + "\" SizeY=\"" + std::to_string(n[1]) + "\" SizeZ=\"" +
       std::to_string(n[2]) + "\" SizeC=\"1\" SizeT=\"1\"";
  const char* axes[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a)
    x += std::string(" PhysicalSize") + axes[a] + "=\"" + roundTripText(s[a]) + "\" PhysicalSize" +
         axes[a] + "Unit=\"" + u + "\"";
  // libtiff writes the host's byte order.
  x += std::string(" BigEndian=\"") + (hostIsBigEndian() ? "true" : "false") + "\">";
  x += "<Channel ID=\"Channel:0:0\" SamplesPerPixel=\"1\"><LightPath/></Channel>";
  x += "<TiffData IFD=\"0\" PlaneCount=\"" + std::to_string(n[2]) + "\"/>";
  // Each slice's position (the first is the origin), as Bio-Formats writes stage positions.
  const glm::dvec3& o = v.origin();
  if (o != glm::dvec3(0.0)) {
    for (int64_t z = 0; z < n[2]; ++z) {
      const glm::dvec3 at = o + glm::dvec3(0.0, 0.0, double(z) * s.z);
      x += "<Plane TheZ=\"" + std::to_string(z) + "\" TheC=\"0\" TheT=\"0\"";
      for (int a = 0; a < 3; ++a)
        x += std::string(" Position") + axes[a] + "=\"" + roundTripText(at[a]) + "\" Position" +
             axes[a] + "Unit=\"" + u + "\"";
      x += "/>";
    }
  }
  return x + "</Pixels></Image></OME>";
}

}  // namespace

std::string encodeTiff(const Volume& volume, const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  MemoryFile file;
  const auto& n = volume.dims();
  const size_t valueBytes = scalarSize(volume.type());
  const size_t rowBytes = size_t(n[0]) * valueBytes;
  const size_t pageBytes = rowBytes * size_t(n[1]);
  // Classic TIFF's offsets are 32 bits: BigTIFF when the data come near them.
  const bool big = uint64_t(pageBytes) * uint64_t(n[2]) > (uint64_t(1) << 32) - (uint64_t(1) << 26);
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, &keepFirstTiffMessage, &file.error);
  TIFFOpenOptionsSetWarningHandlerExtR(options, &ignoreTiffMessage, nullptr);
  std::unique_ptr<TIFF, TiffCloser> tiff(
      TIFFClientOpenExt(name.c_str(), big ? "w8" : "w", &file, &readBytes, &writeBytes, &seekTo,
                        &closeFile, &sizeOf, &noMap, &noUnmap, options));
  TIFFOpenOptionsFree(options);
  auto fail = [&](const std::string& what) {
    return std::runtime_error(path + ": cannot write the TIFF file: " + what +
                              (file.error.empty() ? "" : " (" + file.error + ")"));
  };
  if (!tiff) throw fail("libtiff");
  TIFF* t = tiff.get();
  const bool isFloat = volume.type() == ScalarType::Float32;
  const bool isSigned = volume.type() == ScalarType::Int16;
  const OmeUnit* unit = omeUnit(volume.unit());
  const double perUnit = unit ? unit->perCentimetre : 1.0;  // resolution: pixels per cm
  const std::string description = omeXml(volume, name);
  const uint8_t* data = volume.bytes().data();
  // Rows go through a copy: the predictor may difference the buffer it is given in place.
  std::vector<uint8_t> row(rowBytes);
  for (int64_t z = 0; z < n[2]; ++z) {
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, uint32_t(n[0]));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, uint32_t(n[1]));
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(valueBytes * 8));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, uint16_t(1));
    TIFFSetField(t, TIFFTAG_SAMPLEFORMAT,
                 isFloat    ? SAMPLEFORMAT_IEEEFP
                 : isSigned ? SAMPLEFORMAT_INT
                            : SAMPLEFORMAT_UINT);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    if (!isFloat) TIFFSetField(t, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(t, 0));
    // A rational holds 32-bit parts: a resolution beyond them is left to the OME-XML alone.
    const double xres = perUnit / volume.spacing().x, yres = perUnit / volume.spacing().y;
    if (xres >= 1e-6 && xres <= 1e9 && yres >= 1e-6 && yres <= 1e9) {
      TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, unit ? RESUNIT_CENTIMETER : RESUNIT_NONE);
      TIFFSetField(t, TIFFTAG_XRESOLUTION, float(xres));
      TIFFSetField(t, TIFFTAG_YRESOLUTION, float(yres));
    }
    TIFFSetField(t, TIFFTAG_SOFTWARE, "ewaview");
    if (n[2] > 1) {
      TIFFSetField(t, TIFFTAG_SUBFILETYPE, FILETYPE_PAGE);
      TIFFSetField(t, TIFFTAG_PAGENUMBER, uint16_t(std::min<int64_t>(z, 65535)),
                   uint16_t(std::min<int64_t>(n[2], 65535)));
    }
    if (z == 0) TIFFSetField(t, TIFFTAG_IMAGEDESCRIPTION, description.c_str());
    for (int64_t y = 0; y < n[1]; ++y) {
      std::memcpy(row.data(), data + size_t(z) * pageBytes + size_t(y) * rowBytes, rowBytes);
      if (TIFFWriteScanline(t, row.data(), uint32_t(y), 0) < 0)
        throw fail("slice " + std::to_string(z));
    }
    if (!TIFFWriteDirectory(t)) throw fail("slice " + std::to_string(z));
  }
  tiff.reset();  // flushes
  if (!file.error.empty()) throw fail("libtiff");
  return std::move(file.bytes);
}

std::vector<std::string> tiffLosses(const Volume& volume) {
  std::vector<std::string> losses;
  if (volume.patientFrame())
    losses.push_back("TIFF keeps no patient axes: the slices are written as stored");
  else if (volume.direction() != glm::dmat3(1.0))
    losses.push_back("TIFF keeps no axis directions: the slices are written as stored");
  if (!volume.unit().empty() && !omeUnit(volume.unit()))
    losses.push_back("OME-TIFF has no unit '" + volume.unit() + "': written without one");
  return losses;
}

}  // namespace ewa

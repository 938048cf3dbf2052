// VTK XML ImageData (.vti): extent, origin, spacing and point scalars, appended, inline or ASCII.
#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "io/base64.h"
#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
#include "io/text_numbers.h"
#include "io/volume_layout.h"
#include "io/vtk_binary_array.h"
#include "io/xml_scanner.h"

namespace ewa {

namespace {

// What the XML part of the file says.
struct VtiHeader {
  VtkBinaryFormat format;
  std::array<int64_t, 6> extent{};
  bool haveExtent = false;
  glm::dvec3 origin{0.0};
  glm::dvec3 spacing{1.0};
  XmlTag array;  // the chosen PointData DataArray
  bool haveArray = false;
  size_t inlineBegin = 0, inlineEnd = 0;  // text of an inline array
  bool haveAppended = false;
  uint64_t appendedStart = 0;  // file offset just past the '_' marker
};

// The header is complete once the appended data marker or the end of the file is in.
bool headerComplete(std::string_view text) {
  // Not VTK XML at all: no point reading on (the scan will say so).
  if (text.find("<VTKFile") == std::string_view::npos) return true;
  const size_t appended = text.find("<AppendedData");
  if (appended != std::string_view::npos) {
    const size_t gt = text.find('>', appended);
    return gt != std::string_view::npos && text.find('_', gt) != std::string_view::npos;
  }
  return text.find("</VTKFile>") != std::string_view::npos;
}

std::array<int64_t, 6> parseExtent(const std::string& path, const std::string& text) {
  std::vector<int64_t> v;
  if (!parseInt64List(text, v) || v.size() != 6) failLoad(path, "bad extent " + quoteText(text));
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

glm::dvec3 parseTriple(const std::string& path, const char* what, const std::string& text) {
  std::vector<double> v;
  if (!parseDoubleList(text, v) || v.size() != 3)
    failLoad(path, std::string("bad ") + what + " " + quoteText(text));
  return {v[0], v[1], v[2]};
}

FileScalar parseArrayType(const std::string& path, const std::string* type) {
  if (!type) failLoad(path, "DataArray has no type");
  static const std::pair<const char*, FileScalar> kTypes[] = {
      {"UInt8", FileScalar::UInt8},     {"Int8", FileScalar::Int8},
      {"Int16", FileScalar::Int16},     {"UInt16", FileScalar::UInt16},
      {"Int32", FileScalar::Int32},     {"UInt32", FileScalar::UInt32},
      {"Int64", FileScalar::Int64},     {"UInt64", FileScalar::UInt64},
      {"Float32", FileScalar::Float32}, {"Float64", FileScalar::Float64}};
  for (const auto& [name, t] : kTypes)
    if (*type == name) return t;
  failLoad(path, "unsupported DataArray type " + quoteText(*type) + " (scalar numbers only)");
}

void readFileAttributes(const std::string& path, const XmlTag& tag, VtiHeader& h) {
  const std::string* type = tag.attribute("type");
  if (!type || *type != "ImageData")
    failLoad(path, "VTK file type " + quoteText(type ? *type : "") + " is not ImageData");
  if (const std::string* order = tag.attribute("byte_order")) {
    if (*order == "BigEndian")
      h.format.bigEndian = true;
    else if (*order != "LittleEndian")
      failLoad(path, "bad byte_order " + quoteText(*order));
  }
  if (const std::string* header = tag.attribute("header_type")) {
    if (*header == "UInt64")
      h.format.headerWidth = 8;
    else if (*header != "UInt32")
      failLoad(path, "unsupported header_type " + quoteText(*header));
  }
  if (const std::string* compressor = tag.attribute("compressor");
      compressor && !compressor->empty()) {
    if (*compressor != "vtkZLibDataCompressor")
      failLoad(path, "unsupported compressor " + quoteText(*compressor) +
                         " (only vtkZLibDataCompressor)");
    h.format.zlib = true;
  }
}

VtiHeader scanHeader(const std::string& path, const std::string& text) {
  VtiHeader h;
  XmlScanner scanner(path, text);
  XmlTag tag;
  bool sawFile = false, inPiece = false, inPointData = false;
  std::string scalars;  // PointData Scalars="...": the array to prefer
  int pieces = 0;
  while (scanner.next(tag)) {
    if (!sawFile) {
      if (tag.name != "VTKFile" || tag.closing) failLoad(path, "not a VTK XML file (no <VTKFile>)");
      readFileAttributes(path, tag, h);
      sawFile = true;
    } else if (tag.name == "ImageData" && !tag.closing) {
      if (const std::string* e = tag.attribute("WholeExtent")) {
        h.extent = parseExtent(path, *e);
        h.haveExtent = true;
      }
      if (const std::string* o = tag.attribute("Origin"))
        h.origin = parseTriple(path, "Origin", *o);
      if (const std::string* s = tag.attribute("Spacing"))
        h.spacing = parseTriple(path, "Spacing", *s);
    } else if (tag.name == "Piece") {
      inPiece = !tag.closing && !tag.selfClosing;
      if (tag.closing) continue;
      if (++pieces > 1) failLoad(path, "files with several Pieces are not supported");
      if (const std::string* e = tag.attribute("Extent")) {
        h.extent = parseExtent(path, *e);
        h.haveExtent = true;
      }
    } else if (tag.name == "PointData") {
      inPointData = inPiece && !tag.closing && !tag.selfClosing;
      if (const std::string* s = tag.attribute("Scalars"); s && inPointData) scalars = *s;
    } else if (tag.name == "DataArray" && inPointData && !tag.closing) {
      const std::string* name = tag.attribute("Name");
      const bool preferred = !scalars.empty() && name && *name == scalars;
      const std::string* chosenName = h.array.attribute("Name");
      const bool chosenPreferred =
          h.haveArray && !scalars.empty() && chosenName && *chosenName == scalars;
      const bool take = !h.haveArray || (preferred && !chosenPreferred);
      if (take) {
        h.array = tag;
        h.haveArray = true;
        h.inlineBegin = h.inlineEnd = tag.end;
      }
      if (!tag.selfClosing) {
        // Inline data is the text up to the closing tag, which must come next.
        XmlTag close;
        if (!scanner.next(close) || !close.closing || close.name != "DataArray")
          failLoad(path, "DataArray is not closed");
        if (take) h.inlineEnd = close.begin;
      }
    } else if (tag.name == "AppendedData" && !tag.closing) {
      const std::string* encoding = tag.attribute("encoding");
      if (!encoding || *encoding != "raw")
        failLoad(path, "unsupported AppendedData encoding " + quoteText(encoding ? *encoding : "") +
                           " (need raw)");
      size_t i = tag.end;
      while (i < text.size() &&
             (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n'))
        ++i;
      if (i >= text.size() || text[i] != '_')
        failLoad(path, "AppendedData does not start with '_'");
      h.haveAppended = true;
      h.appendedStart = i + 1;
      break;  // binary data follows: no more XML to scan
    } else if (tag.name == "VTKFile" && tag.closing) {
      break;
    }
  }
  if (!sawFile) failLoad(path, "not a VTK XML file (no <VTKFile>)");
  if (!h.haveExtent) failLoad(path, "no WholeExtent or Piece Extent");
  if (!h.haveArray) failLoad(path, "no PointData DataArray");
  return h;
}

std::array<int64_t, 3> dimsOfExtent(const std::string& path, const std::array<int64_t, 6>& e) {
  std::array<int64_t, 3> dims{};
  for (int a = 0; a < 3; ++a) {
    int64_t span = 0;
    if (e[2 * a + 1] < e[2 * a] || __builtin_sub_overflow(e[2 * a + 1], e[2 * a], &span) ||
        span == std::numeric_limits<int64_t>::max()) {
      failLoad(path, "bad extent: axis " + std::to_string(a) + " runs from " +
                         std::to_string(e[2 * a]) + " to " + std::to_string(e[2 * a + 1]));
    }
    dims[a] = span + 1;
  }
  return dims;
}

}  // namespace

Volume loadVti(const std::string& path, int channel) {
  const std::string text =
      readFilePrefix(path, std::numeric_limits<uint64_t>::max(), headerComplete);
  const VtiHeader h = scanHeader(path, text);

  VolumeLayout layout;
  layout.dims = dimsOfExtent(path, h.extent);
  layout.spacing = h.spacing;
  // VTK places point (i,j,k) of the extent at Origin + (i,j,k) * Spacing.
  layout.origin =
      h.origin +
      glm::dvec3(double(h.extent[0]), double(h.extent[2]), double(h.extent[4])) * h.spacing;
  layout.type = parseArrayType(path, h.array.attribute("type"));
  layout.bigEndian = h.format.bigEndian;
  int64_t components = 1;  // interleaved in each point (colour, vectors)
  if (const std::string* c = h.array.attribute("NumberOfComponents");
      c && !parseInt64(trim(*c), components))
    failLoad(path, "bad NumberOfComponents " + quoteText(*c));
  const uint64_t total = componentDataByteCount(path, layout.dims, layout.type, components);

  const std::string* format = h.array.attribute("format");
  const std::string fmt = format ? *format : "";
  std::vector<uint8_t> bytes;
  if (fmt == "appended") {
    if (!h.haveAppended) failLoad(path, "DataArray is appended but there is no AppendedData");
    const std::string* offsetText = h.array.attribute("offset");
    int64_t offset = 0;
    if (!offsetText || !parseInt64(*offsetText, offset) || offset < 0)
      failLoad(path, "bad DataArray offset " + quoteText(offsetText ? *offsetText : ""));
    const uint64_t start = h.appendedStart + static_cast<uint64_t>(offset);
    if (start < h.appendedStart || start > regularFileSize(path))
      failLoad(path,
               "DataArray offset " + std::to_string(offset) + " points past the end of the file");
    bytes = decodeVtkBinaryArray(path, FileSource(path, start), h.format, total);
  } else if (fmt == "binary") {
    std::vector<uint8_t> decoded;
    if (!decodeBase64(std::string_view(text).substr(h.inlineBegin, h.inlineEnd - h.inlineBegin),
                      decoded))
      failLoad(path, "inline DataArray is not valid base64");
    bytes = decodeVtkBinaryArray(path, MemorySource(path, std::move(decoded)), h.format, total);
  } else if (fmt == "ascii") {
    // Numbers as text, in native order once encoded.
    const std::string_view inlineText =
        std::string_view(text).substr(h.inlineBegin, h.inlineEnd - h.inlineBegin);
    bytes = encodeValues(
        parseTextNumbers(path, inlineText, total / fileScalarSize(layout.type), "ASCII DataArray"),
        layout.type);
    layout.bigEndian = hostIsBigEndian();
  } else {
    failLoad(path, "unsupported DataArray format " + quoteText(fmt) +
                       " (need appended, binary or ascii)");
  }
  bytes = pickComponent(path, std::move(bytes), components, channel, layout);
  return makeVolume(path, layout, std::move(bytes));
}

}  // namespace ewa

// TIFF plane orders: ImageJ's description lines and OME-XML's Pixels element, page to slice.
#include "io/tiff_planes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "io/file_bytes.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/text_fields.h"
#include "io/xml_scanner.h"

namespace ewa {

namespace {

constexpr int64_t kMaxPlanes = int64_t(1) << 30;  // per dimension: no product overflows
constexpr size_t kMaxBlocks = size_t(1) << 20;    // TiffData elements read

std::string localName(const std::string& name) {  // "ome:Pixels" in prefixed documents
  const size_t colon = name.rfind(':');
  return name.substr(colon == std::string::npos ? 0 : colon + 1);
}

// ImageJ's description: "key=value" lines.
std::string imageJField(const std::string& description, const std::string& key) {
  for (const std::string& line : splitWords(description, "\n")) {
    if (line.compare(0, key.size() + 1, key + "=") == 0) return trim(line.substr(key.size() + 1));
  }
  return "";
}

// A count from 1 to kMaxPlanes, or `fallback`.
int64_t count(const std::string& text, int64_t fallback) {
  int64_t v = 0;
  return parseInt64(trim(text), v) && v >= 1 && v <= kMaxPlanes ? v : fallback;
}

// An index from 0 to kMaxPlanes, or `fallback`.
int64_t index(const std::string* text, int64_t fallback) {
  int64_t v = 0;
  return text && parseInt64(trim(*text), v) && v >= 0 && v <= kMaxPlanes ? v : fallback;
}

double positive(const std::string& text) {
  double v = 0.0;
  return parseDouble(trim(text), v) && v > 0.0 && std::isfinite(v) ? v : 0.0;
}

// A finite number, or 0.
double finite(const std::string* text) {
  double v = 0.0;
  return text && parseDouble(trim(*text), v) && std::isfinite(v) ? v : 0.0;
}

// Metres in one `unit` (OME's UnitsLength spellings), or 0 when it is not a length we know.
double metres(const std::string& unit) {
  const std::string name = lengthUnitName(unit);
  if (name == "m") return 1.0;
  if (name == "cm") return 1e-2;
  if (name == "mm") return 1e-3;
  if (name == "\xC2\xB5m") return 1e-6;
  if (name == "nm") return 1e-9;
  if (name == "pm") return 1e-12;
  if (name == "\xC3\x85") return 1e-10;  // Å, OME's angstrom
  return 0.0;
}

// The first slice's position from a Plane element (TheZ, TheC and TheT 0) into `o.origin`, in
// `o.unit`: each position in its own unit, OME's "reference frame" when not named.
void readPlanePosition(const XmlTag& tag, TiffPlaneOrder& o) {
  if (index(tag.attribute("TheZ"), -1) != 0 || index(tag.attribute("TheC"), 0) != 0 ||
      index(tag.attribute("TheT"), 0) != 0)
    return;
  const char* axes[3] = {"X", "Y", "Z"};
  std::array<double, 3> at{};
  for (int a = 0; a < 3; ++a) {
    const std::string key = std::string("Position") + axes[a];
    const std::string* unitText = tag.attribute(key + "Unit");
    const std::string unit = unitText ? *unitText : "reference frame";
    at[a] = finite(tag.attribute(key));
    if (at[a] == 0.0) continue;
    // A length in another length: converted; a length with no unit, or none with one: unknown.
    const double from = metres(unit), to = metres(o.unit);
    const bool unitless = unit == "reference frame" || unit == "pixel";
    if (from > 0.0 && to > 0.0)
      at[a] *= from / to;
    else if (!(unitless && o.unit.empty()))
      return;
  }
  o.hasOrigin = true;
  o.origin = at;
}

// The TiffData elements after a Pixels tag, up to its end, kept when one names another file;
// the first slice's position from its Plane elements.
std::vector<TiffDataBlock> pixelsChildren(XmlScanner& scanner, const std::string& path,
                                          TiffPlaneOrder& o) {
  std::vector<TiffDataBlock> blocks;
  size_t open = SIZE_MAX;  // the TiffData whose UUID may follow
  XmlTag tag;
  while (blocks.size() < kMaxBlocks && scanner.next(tag)) {
    const std::string name = localName(tag.name);
    if (tag.closing) {
      if (name == "Pixels") break;
      if (name == "TiffData") open = SIZE_MAX;
      continue;
    }
    if (name == "TiffData") {
      TiffDataBlock b;
      b.ifdGiven = tag.attribute("IFD") != nullptr;
      b.ifd = index(tag.attribute("IFD"), 0);
      b.firstZ = index(tag.attribute("FirstZ"), 0);
      b.firstC = index(tag.attribute("FirstC"), 0);
      b.firstT = index(tag.attribute("FirstT"), 0);
      b.planeCount = index(tag.attribute("PlaneCount"), -1);
      blocks.push_back(b);
      open = tag.selfClosing ? SIZE_MAX : blocks.size() - 1;
    } else if (name == "Plane" && !o.hasOrigin) {
      readPlanePosition(tag, o);
    } else if (name == "UUID" && open != SIZE_MAX) {
      if (const std::string* file = tag.attribute("FileName")) blocks[open].file = *file;
    }
  }
  const std::string self = std::filesystem::path(path).filename().string();
  for (const TiffDataBlock& b : blocks)
    if (!b.file.empty() && b.file != self) return blocks;
  return {};
}

TiffPlaneOrder imageJOrder(const std::string& text) {
  TiffPlaneOrder o;
  o.kind = "ImageJ";
  o.channels = count(imageJField(text, "channels"), 1);  // of pages; divided by samples below
  o.frames = count(imageJField(text, "frames"), 1);
  o.slices = count(imageJField(text, "slices"), o.frames > 1 ? 1 : 0);
  o.sizeZ = positive(imageJField(text, "spacing"));
  o.unit = imageJField(text, "unit");
  return o;
}

TiffPlaneOrder omeOrder(const std::string& path, const std::string& text, int64_t samples) {
  XmlScanner scanner(path, text);
  XmlTag tag;
  while (scanner.next(tag)) {
    if (tag.closing || localName(tag.name) != "Pixels") continue;
    auto value = [&](const char* key) {
      const std::string* v = tag.attribute(key);
      return v ? *v : std::string();
    };
    TiffPlaneOrder o;
    o.kind = "OME";
    const std::string order = value("DimensionOrder");  // "XYZCT", ...
    if (order.size() == 5 && order.compare(0, 2, "XY") == 0) {
      std::string rest = order.substr(2);
      std::string sorted = rest;
      std::sort(sorted.begin(), sorted.end());
      if (sorted == "CTZ") o.order = rest;
    }
    o.slices = count(value("SizeZ"), 1);
    o.channels = std::max<int64_t>(1, count(value("SizeC"), 1) / std::max<int64_t>(samples, 1));
    o.frames = count(value("SizeT"), 1);
    // Each size in its own unit (micrometres by default, as the schema has it), all given in X's.
    auto unitOf = [&](const char* key) {
      const std::string u = value(key);
      return u.empty() ? std::string("\xC2\xB5m") : u;
    };
    o.unit = unitOf("PhysicalSizeXUnit");
    if (o.unit == "reference frame" || o.unit == "pixel") o.unit.clear();  // OME's "no length"
    auto inXUnits = [&](const char* size, const char* unit) {
      const double from = metres(unitOf(unit)), to = metres(o.unit);
      const double v = positive(value(size));
      return from > 0.0 && to > 0.0 ? v * (from / to) : v;
    };
    o.sizeX = positive(value("PhysicalSizeX"));
    o.sizeY = inXUnits("PhysicalSizeY", "PhysicalSizeYUnit");
    o.sizeZ = inXUnits("PhysicalSizeZ", "PhysicalSizeZUnit");
    if (o.sizeY == 0.0) o.sizeY = o.sizeX;  // square pixels when only X is given
    if (!tag.selfClosing) o.blocks = pixelsChildren(scanner, path, o);
    return o;
  }
  return {};
}

}  // namespace

TiffPlaneOrder tiffPlaneOrder(const std::string& path, const std::string& description,
                              int64_t samples) {
  if (description.compare(0, 7, "ImageJ=") == 0) {
    TiffPlaneOrder o = imageJOrder(description);
    o.channels = std::max<int64_t>(1, o.channels / std::max<int64_t>(samples, 1));
    return o;
  }
  // OME-XML, its elements plain or prefixed ("<ome:OME>"): read on to its Pixels element.
  if (description.find("OME") == std::string::npos ||
      description.find("Pixels") == std::string::npos)
    return {};
  try {
    return omeOrder(path, description, samples);
  } catch (const LoadError&) {
    return {};  // unreadable XML: the pages as a plain stack
  }
}

namespace {

// Plane `plane` (in the dimension order) as z, c, t.
void planeIndices(const TiffPlaneOrder& o, int64_t plane, int64_t index[3]) {
  for (size_t n = 0; n < o.order.size(); ++n) {
    const int slot = o.order[n] == 'Z' ? 0 : o.order[n] == 'C' ? 1 : 2;
    const int64_t size = slot == 0 ? o.slices : slot == 1 ? o.channels : o.frames;
    index[slot] = n + 1 == o.order.size() ? plane : plane % size;
    plane /= size;
  }
}

// The plane number of z, c, t in the dimension order (each size at most kMaxPlanes, the
// planes of one file far fewer: callers only add counts of pages).
int64_t planeNumber(const TiffPlaneOrder& o, int64_t z, int64_t c, int64_t t) {
  int64_t plane = 0;
  for (size_t n = o.order.size(); n-- > 0;) {
    const int slot = o.order[n] == 'Z' ? 0 : o.order[n] == 'C' ? 1 : 2;
    const int64_t size = slot == 0 ? o.slices : slot == 1 ? o.channels : o.frames;
    const int64_t i = slot == 0 ? z : slot == 1 ? c : t;
    if (i >= size) return -1;
    if (plane > (INT64_MAX - i) / size) return -1;
    plane = plane * size + i;
  }
  return plane;
}

}  // namespace

std::string omeFileBeside(const std::string& path, const std::string& xmlFile,
                          const std::string& name, const std::string& namer) {
  if (name.find_first_of("/\\") != std::string::npos || name == "." || name == "..")
    failLoad(path, namer + " names " + quoteText(name) + ", not a file beside it");
  return siblingPath(xmlFile, name);
}

std::map<int64_t, TiffPlaneSource> omePlaneSources(
    const std::string& path, const TiffPlaneOrder& order, int64_t channel, int64_t frame,
    const std::function<int64_t(const std::string&)>& pagesIn) {
  namespace fs = std::filesystem;
  std::map<int64_t, TiffPlaneSource> out;  // not sized by SizeZ: only slices found
  std::map<std::string, int64_t> pages;
  auto pagesOf = [&](const std::string& file) {
    auto it = pages.find(file);
    if (it == pages.end()) it = pages.emplace(file, std::max<int64_t>(0, pagesIn(file))).first;
    return it->second;
  };
  const int64_t slices = std::max<int64_t>(order.slices, 1);
  for (const TiffDataBlock& b : order.blocks) {
    std::string file = path;
    if (!b.file.empty()) {
      file = omeFileBeside(path, path, b.file, "a TiffData");
    }
    const int64_t first = planeNumber(order, b.firstZ, b.firstC, b.firstT);
    if (first < 0) continue;
    // The pages it holds: PlaneCount, else 1 with an IFD, else the rest of the file.
    int64_t count = b.planeCount >= 0 ? b.planeCount : b.ifdGiven ? 1 : -1;
    int64_t firstIndex[3];
    planeIndices(order, first, firstIndex);
    const bool firstWanted = firstIndex[1] == channel && firstIndex[2] == frame;
    if (count < 0 || firstWanted || count > 1) {
      const int64_t have = pagesOf(file);
      if (have == 0) {
        if (!firstWanted) continue;  // a file this channel and time point do not need
        failLoad(path, "the dataset's file " + quoteText(fs::path(file).filename().string()) +
                           " is missing or not a TIFF file");
      }
      const int64_t available = std::max<int64_t>(0, have - b.ifd);
      count = count < 0 ? available : std::min(count, available);
    }
    for (int64_t k = 0; k < count; ++k) {
      int64_t i[3];
      planeIndices(order, first + k, i);
      if (i[1] == channel && i[2] == frame && i[0] < slices) out[i[0]] = {file, b.ifd + k};
    }
  }
  return out;
}

std::string omeMetadataFile(const std::string& description) {
  if (description.find("BinaryOnly") == std::string::npos) return "";
  try {
    XmlScanner scanner("", description);
    XmlTag tag;
    while (scanner.next(tag)) {
      if (tag.closing || localName(tag.name) != "BinaryOnly") continue;
      const std::string* file = tag.attribute("MetadataFile");
      return file ? *file : "";
    }
  } catch (const LoadError&) {
  }
  return "";
}

int64_t tiffSliceOfPage(const TiffPlaneOrder& o, int64_t page, int64_t channel, int64_t frame) {
  int64_t index[3] = {0, 0, 0};  // z, c, t
  int64_t rest = page;
  for (size_t n = 0; n < o.order.size(); ++n) {
    const int slot = o.order[n] == 'Z' ? 0 : o.order[n] == 'C' ? 1 : 2;
    const int64_t size = slot == 0 ? o.slices : slot == 1 ? o.channels : o.frames;
    // The slowest dimension, or one of unknown size (a plain stack's Z), takes what is left.
    if (n + 1 == o.order.size() || size <= 0) {
      index[slot] = rest;
      rest = 0;
    } else {
      index[slot] = rest % size;
      rest /= size;
    }
  }
  if (index[1] != channel || index[2] != frame) return -1;
  return o.slices > 0 && index[0] >= o.slices ? -1 : index[0];
}

}  // namespace ewa

// checkDicomStructure: element lengths against the file size, before GDCM allocates by them.
#include "io/dicom_guard.h"

#include <gdcmDicts.h>
#include <gdcmGlobal.h>
#include <gdcmVR.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/byte_order.h"
#include "io/dicom_colour.h"
#include "io/dicom_dose_grid.h"
#include "io/dicom_inflate.h"
#include "io/dicom_series.h"
#include "io/file_bytes.h"
#include "io/file_listing.h"
#include "io/format_loaders.h"
#include "io/jpeg_header_check.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

namespace {

// VRs whose explicit form has two reserved bytes and a 4-byte length.
bool longVr(const uint8_t* vr) {
  static const char* const kLong[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                      "SV", "UC", "UN", "UR", "UT", "UV"};
  for (const char* v : kLong)
    if (vr[0] == v[0] && vr[1] == v[1]) return true;
  return false;
}

// One of the standard's value representations (GDCM falls back to other readers, which assert,
// on anything else).
bool isVr(const uint8_t* vr) {
  static const char kAll[] = "AEASATCSDADSDTFLFDISLOLTOBODOFOLOVOWPNSHSLSQSSSTSVTMUCUIULUNURUSUTUV";
  for (size_t i = 0; i + 1 < sizeof kAll; i += 2)
    if (vr[0] == uint8_t(kAll[i]) && vr[1] == uint8_t(kAll[i + 1])) return true;
  return false;
}

// Whether an explicit VR fits the dictionary's for a tag GDCM reads through its typed
// attributes (the image pixel module, group 0028), which assert on an incompatible one (found
// by fuzzing: Columns as SS). Tags the dictionary does not know pass.
bool vrFitsDictionary(uint16_t group, uint16_t element, const uint8_t* vr) {
  const gdcm::DictEntry& entry =
      gdcm::Global::GetInstance().GetDicts().GetDictEntry(gdcm::Tag(group, element));
  const gdcm::VR expected = entry.GetVR();
  if (expected == gdcm::VR::INVALID || expected == gdcm::VR::VR_END) return true;
  const std::string code(reinterpret_cast<const char*>(vr), 2);
  return expected.Compatible(gdcm::VR(gdcm::VR::GetVRType(code.c_str())));
}

// Where the walk is: inside a sequence, an item, or encapsulated pixel data (whose items hold
// compressed bytes), each ending at a byte offset or, with undefined length, at a delimiter.
struct Container {
  enum Kind { Sequence, Item, Fragments } kind;
  size_t end;        // kUndefined: ends at its delimiter
  size_t items = 0;  // fragments: those walked (the first is the offset table)
};
constexpr size_t kUndefined = SIZE_MAX;

// How deep sequences may nest. GDCM reads nested items recursively and overflows its stack
// (SIGSEGV) a few thousand levels down (3,000 still load); real files need a handful (enhanced
// functional groups 3, structured report content trees rarely 20): 128 leaves room for any of
// them and stays far below the crash, so a file past it is hostile.
constexpr size_t kMaxSequenceDepth = 128;

struct Walk {
  const std::vector<uint8_t>& bytes;
  std::string problem;  // empty while the walk is fine
  std::vector<Container> open;
  bool jpeg = false;      // the transfer syntax is JPEG: each frame's header is checked
  bool jpeg2000 = false;  // JPEG 2000: each codestream's image size against the header's
  bool jpegLs = false;    // JPEG-LS: each frame's size against the header's
  // A bare implicit data set: GDCM reads it up to the file's length, summing the lengths of
  // items, and asserts on an item whose contents' length is odd (found by fuzzing), so items
  // and the elements inside them must have even lengths, as the standard has it.
  bool evenLengths = false;
  // Zero padding after the data set: GDCM stops cleanly at fewer than 4 bytes (no whole tag);
  // in a little-endian file it reads each 8 zero bytes as an empty element (0000,0000) first
  // (its deflate and big-endian readers do not), and asserts on a tag with 4 to 7 bytes left.
  bool zeroElements = false;
  // The data set's own (0028,0010), (0011), (0002), (0100).
  int64_t rows = 0, columns = 0, samples = 1, bitsAllocated = 0;
  std::string photometric{};  // (0028,0004), trimmed
  // The data set's own values GDCM's RT Dose reading depends on (doseGridHeaderProblem):
  // SOP class (0008,0016) or, in the meta header, (0002,0002); (3004,000C); whether (0028,0008)
  // is there.
  std::string sopClass{}, gridFrameOffsets{};
  bool hasFrameCount = false;

  // Walks elements from `pos` to the end (or, with `metaOnly`, while the group is 0002). Items
  // and delimiters must sit where they belong: GDCM asserts (aborts) on one out of place.
  // Returns where it stopped.
  size_t run(size_t pos, bool explicitVr, bool bigEndian, bool metaOnly) {
    const size_t n = bytes.size();
    while (problem.empty()) {
      while (!open.empty() && open.back().end != kUndefined && pos >= open.back().end) {
        if (pos > open.back().end) return fail(pos, "an element overruns its sequence or item");
        open.pop_back();
      }
      if (pos >= n) break;
      // Zero bytes after the last top-level element are padding, where GDCM reads them.
      if (open.empty() && !metaOnly && zeroFrom(pos)) {
        if (!paddingReadable(n - pos))
          return fail(pos, std::to_string(n - pos) +
                               " zero bytes after the last element: padding of a length GDCM "
                               "cannot read");
        break;
      }
      if (n - pos < 8) return fail(pos, "an element header is cut short");
      const bool big = bigEndian && !metaOnly;
      const auto group = uint16_t(readUnsigned(&bytes[pos], 2, big));
      const auto element = uint16_t(readUnsigned(&bytes[pos + 2], 2, big));
      if (metaOnly && group != 0x0002) return pos;
      const Container::Kind top = open.empty() ? Container::Item : open.back().kind;
      if (group == 0xfffe) {
        const uint64_t length = readUnsigned(&bytes[pos + 4], 4, big);
        if (evenLengths && length != 0xffffffffu && length % 2 != 0)
          return fail(pos, "an item of odd length " + std::to_string(length));
        pos += 8;
        // A delimiter's length is 0; GDCM allocates what it claims (found by fuzzing: 4 GiB).
        if ((element == 0xe00d || element == 0xe0dd) && length != 0)
          return fail(pos - 8, "a delimiter of length " + std::to_string(length));
        if (element == 0xe000 && top == Container::Fragments) {
          if (length > n - pos) return fail(pos, "a pixel data fragment is cut short");
          // GDCM's JPEG codec aborts on headers libjpeg only warns about: checked first.
          // The image's own fragments (not an icon's, inside a sequence) after the offset table.
          if (open.size() == 1 && open.back().items++ > 0) {
            if (jpeg) {
              const std::string bad = jpegHeaderProblem(&bytes[pos], size_t(length));
              if (!bad.empty())
                return fail(pos, "the JPEG header of a pixel data fragment: " + bad);
            }
            if (jpegLs) {
              const std::string bad = jpegLsHeaderProblem(&bytes[pos], size_t(length), columns,
                                                          rows, samples, bitsAllocated);
              if (!bad.empty())
                return fail(pos, "the JPEG-LS header of a pixel data fragment: " + bad);
            }
            if (jpeg2000) {
              const std::string bad =
                  jpeg2000HeaderProblem(&bytes[pos], size_t(length), columns, rows, samples);
              if (!bad.empty())
                return fail(pos, "the JPEG 2000 header of a pixel data fragment: " + bad);
            }
          }
          pos += size_t(length);
        } else if (element == 0xe000 && top == Container::Sequence) {
          if (length != 0xffffffffu && length > n - pos)
            return fail(pos, "an item claims " + std::to_string(length) + " bytes");
          open.push_back({Container::Item, length == 0xffffffffu ? kUndefined : pos + length});
        } else if (element == 0xe00d && !open.empty() && top == Container::Item &&
                   open.back().end == kUndefined) {
          open.pop_back();
        } else if (element == 0xe0dd && !open.empty() && top != Container::Item &&
                   open.back().end == kUndefined) {
          open.pop_back();
        } else {
          return fail(pos - 8, "an item or delimiter out of place");
        }
        continue;
      }
      if (top != Container::Item) return fail(pos, "an element outside any item");
      uint64_t length = 0;
      bool sequence = false;
      const bool pixelData = group == 0x7fe0 && element == 0x0010;
      if (explicitVr || metaOnly) {
        const uint8_t* vr = &bytes[pos + 4];
        if (!isVr(vr)) return fail(pos, "an element has no valid VR");
        const uint64_t declared =
            longVr(vr) && n - pos >= 12 ? readUnsigned(&bytes[pos + 8], 4, big) : 0;
        // GDCM asserts unless an undefined length is a sequence's, an unknown-VR element's or
        // encapsulated pixel data's (OB or OW), and unless pixel data is no sequence.
        const bool sq = vr[0] == 'S' && vr[1] == 'Q', un = vr[0] == 'U' && vr[1] == 'N';
        const bool obow = vr[0] == 'O' && (vr[1] == 'B' || vr[1] == 'W');
        if (pixelData && (sq || (declared == 0xffffffffu && !obow)))
          return fail(pos, "pixel data (7FE0,0010) of VR " + std::string(vr, vr + 2));
        if (declared == 0xffffffffu && !sq && !un && !pixelData)
          return fail(pos, "an undefined length for VR " + std::string(vr, vr + 2));
        if ((group == 0x0028 || isScannedDicomTag(group, element)) && !metaOnly &&
            !vrFitsDictionary(group, element, vr))
          return fail(pos, "element (" + hex(group) + "," + hex(element) + ") of VR " +
                               std::string(vr, vr + 2));
        if (longVr(vr)) {
          if (n - pos < 12) return fail(pos, "an element header is cut short");
          length = readUnsigned(&bytes[pos + 8], 4, big);
          pos += 12;
        } else {
          length = readUnsigned(&bytes[pos + 6], 2, big);
          pos += 8;
        }
        sequence = vr[0] == 'S' && vr[1] == 'Q';
      } else {
        length = readUnsigned(&bytes[pos + 4], 4, big);
        // A defined length in the implicit syntax is opaque here: GDCM keeps such a value's
        // bytes and parses them only when asked (a 5,000-level bomb of them reads), so only
        // undefined lengths nest.
        pos += 8;
      }
      if (evenLengths && !open.empty() && length != 0xffffffffu && length % 2 != 0)
        return fail(pos, "element (" + hex(group) + "," + hex(element) + ") of odd length " +
                             std::to_string(length));
      if ((sequence || length == 0xffffffffu) && sequenceDepth() >= kMaxSequenceDepth)
        return fail(pos,
                    "sequences nested more than " + std::to_string(kMaxSequenceDepth) + " deep");
      if (length == 0xffffffffu) {  // undefined length: items follow, then a delimiter
        open.push_back({group == 0x7fe0 ? Container::Fragments : Container::Sequence, kUndefined});
        continue;
      }
      if (length > n - pos) {
        return fail(pos, "element (" + hex(group) + "," + hex(element) + ") claims " +
                             std::to_string(length) + " bytes but only " + std::to_string(n - pos) +
                             " remain");
      }
      if (sequence) {
        open.push_back({Container::Sequence, pos + size_t(length)});
        continue;
      }
      if (group == 0x0028 && open.empty() && length == 2) {
        const auto value = int64_t(readUnsigned(&bytes[pos], 2, big));
        if (element == 0x0010) rows = value;
        if (element == 0x0011) columns = value;
        if (element == 0x0002) samples = value;
        if (element == 0x0100) bitsAllocated = value;
      }
      if (open.empty()) noteDoseValue(group, element, pos, length);
      if (group == 0x0028 && element == 0x0004 && open.empty() && length <= 64) {
        photometric.assign(reinterpret_cast<const char*>(&bytes[pos]), size_t(length));
        while (!photometric.empty() && (photometric.back() == ' ' || photometric.back() == '\0'))
          photometric.pop_back();
      }
      // GDCM asserts that a retired Recognition Code names ACR-NEMA or MIPS.
      if (group == 0x0008 && element == 0x0010 && open.empty() && !recognitionCodeOk(pos, length))
        return fail(pos, "a Recognition Code (0008,0010) that is not ACR-NEMA");
      pos += size_t(length);
    }
    if (problem.empty() && !metaOnly && !open.empty())
      return fail(pos, "a sequence or item is not closed (truncated file?)");
    return pos;
  }

  void noteDoseValue(uint16_t group, uint16_t element, size_t pos, uint64_t length) {
    const auto text = [&] {
      return std::string(reinterpret_cast<const char*>(&bytes[pos]),
                         size_t(std::min<uint64_t>(length, 1 << 20)));
    };
    if ((group == 0x0002 && element == 0x0002) || (group == 0x0008 && element == 0x0016)) {
      const std::string uid = text();
      if (sopClass.empty() || uid.rfind(kRtDoseStorageUid, 0) == 0) sopClass = uid;
    }
    if (group == 0x3004 && element == 0x000c) gridFrameOffsets = text();
    if (group == 0x0028 && element == 0x0008) hasFrameCount = true;
  }

  bool paddingReadable(size_t zeros) const { return zeros < 4 || (zeroElements && zeros % 8 < 4); }

  size_t sequenceDepth() const {
    return size_t(std::count_if(open.begin(), open.end(),
                                [](const Container& c) { return c.kind != Container::Item; }));
  }

  // Whether every byte from `pos` to the end is zero.
  bool zeroFrom(size_t pos) const {
    return std::all_of(bytes.begin() + ptrdiff_t(pos), bytes.end(),
                       [](uint8_t b) { return b == 0; });
  }

  bool recognitionCodeOk(size_t pos, uint64_t length) const {
    const std::string value(reinterpret_cast<const char*>(&bytes[pos]), size_t(length));
    for (const char* ok : {"ACR-NEMA", "ACRNEMA", "MIPS 2.0"})
      if (value.compare(0, std::strlen(ok), ok) == 0) return true;
    return false;
  }

  size_t fail(size_t pos, const std::string& what) {
    problem = what + " at byte " + std::to_string(pos);
    return bytes.size();
  }

  static std::string hex(uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "%04X", v);
    return text;
  }
};

// The transfer syntax UID in the meta header's (0002,0010), or "".
std::string transferSyntax(const std::vector<uint8_t>& b, size_t from, size_t to) {
  for (size_t p = from; p + 8 <= to;) {
    const auto element = uint16_t(readUnsigned(&b[p + 2], 2, false));
    const bool longForm = longVr(&b[p + 4]);
    const size_t header = longForm ? 12 : 8;
    const uint64_t length =
        longForm ? readUnsigned(&b[p + 8], 4, false) : readUnsigned(&b[p + 6], 2, false);
    if (p + header + length > to) return "";
    if (element == 0x0010) {
      std::string uid(reinterpret_cast<const char*>(&b[p + header]), size_t(length));
      while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
      return uid;
    }
    p += header + size_t(length);
  }
  return "";
}

// How a file holds DICOM: after the Part 10 preamble, or as a bare data set from byte 0 (an
// ACR-NEMA file, or a data set saved without its preamble and meta header).
enum class DicomStart { None, Part10, BareExplicit, BareImplicit, BareBigEndian };

// The tag of the element at `pos` and where the next one starts (0 when its header does not
// fit in `head`), read as explicit or implicit VR in the given byte order.
struct BareElement {
  uint16_t group = 0, element = 0;
  size_t next = 0;
};
BareElement bareElement(const std::vector<uint8_t>& head, size_t pos, bool explicitVr, bool big) {
  BareElement e;
  if (head.size() < pos + 12) return e;
  e.group = uint16_t(readUnsigned(&head[pos], 2, big));
  e.element = uint16_t(readUnsigned(&head[pos + 2], 2, big));
  uint64_t length = 0, header = 8;
  if (!explicitVr)
    length = readUnsigned(&head[pos + 4], 4, big);
  else if (longVr(&head[pos + 4]))
    length = readUnsigned(&head[pos + 8], 4, big), header = 12;
  else
    length = readUnsigned(&head[pos + 6], 2, big);
  if (length <= head.size()) e.next = pos + size_t(header + length);
  return e;
}

// GDCM reads a file without "DICM" at byte 128 from byte 0, telling its encoding by its first
// element (FileMetaInformation::ReadCompat): group 0008 little-endian, explicit when a VR
// follows the tag. Only such a start whose second element follows in tag order, within the
// first 4 KiB, counts: other files that happen to start with 08 00 are not DICOM.
DicomStart dicomStart(const std::string& path) {
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec || size < 16) return DicomStart::None;
  if (size >= 132 &&
      std::memcmp(readFileRange(path, 128, 4, "DICOM preamble").data(), "DICM", 4) == 0)
    return DicomStart::Part10;
  // A bare data set is told by a few bytes only: looked for in files named as DICOM files are
  // (IM0001, a UID, .dcm, .acr, ...), never in a .raw or .dat whose data might start alike.
  const std::string name = std::filesystem::path(path).filename().string();
  if (!mayBeDicomByName(name)) return DicomStart::None;
  const std::vector<uint8_t> head =
      readFileRange(path, 0, std::min<uint64_t>(size, 4096), "DICOM data set");
  for (const bool big : {false, true}) {
    if (readUnsigned(head.data(), 2, big) != 0x0008) continue;
    const char vr[3] = {char(head[4]), char(head[5]), 0};
    const bool explicitVr = gdcm::VR::GetVRType(vr) != gdcm::VR::VR_END;
    const BareElement first = bareElement(head, 0, explicitVr, big);
    if (first.next == 0) continue;
    const BareElement second = bareElement(head, first.next, explicitVr, big);
    const bool ordered =
        second.group > 0x0008 || (second.group == 0x0008 && second.element > first.element);
    if (ordered)
      return big          ? DicomStart::BareBigEndian
             : explicitVr ? DicomStart::BareExplicit
                          : DicomStart::BareImplicit;
  }
  return DicomStart::None;
}

// GDCM's image reader asserts on some RT Dose headers (doseGridHeaderProblem); the SOP class
// from the meta header (`metaSopClass`) or the data set's own.
void checkDoseGrid(const std::string& path, const std::string& metaSopClass, const Walk& walk) {
  const bool dose = metaSopClass.rfind(kRtDoseStorageUid, 0) == 0 ||
                    walk.sopClass.rfind(kRtDoseStorageUid, 0) == 0;
  const std::string problem =
      dose ? doseGridHeaderProblem(walk.gridFrameOffsets, walk.hasFrameCount) : std::string();
  if (!problem.empty()) failLoad(path, problem);
}

}  // namespace

bool looksLikeDicom(const std::string& path) {
  return dicomStart(path) != DicomStart::None;
}

DicomStructure checkDicomStructure(const std::string& path) {
  const uint64_t size = regularFileSize(path);
  // Other files in a folder (notes, pictures) are only looked at as far as their start.
  const DicomStart start = dicomStart(path);
  if (start == DicomStart::None) return DicomStructure::NotDicom;
  // GDCM refuses implicit big-endian (ACR-NEMA's own byte order) by throwing a bare string.
  if (start == DicomStart::BareBigEndian)
    failLoad(path,
             "a DICOM data set in big-endian byte order without the Part 10 header (old "
             "ACR-NEMA): not read");
  checkAllocation(path, size, "file");
  const std::vector<uint8_t> bytes = readFileRange(path, 0, size, "file");
  Walk walk{bytes, {}, {}};
  if (start != DicomStart::Part10) {
    const bool explicitVr = start == DicomStart::BareExplicit;
    walk.evenLengths = !explicitVr;
    walk.zeroElements = true;
    walk.run(0, explicitVr, false, false);
    if (!walk.problem.empty()) failLoad(path, "corrupt or truncated DICOM data: " + walk.problem);
    checkDoseGrid(path, "", walk);
    const std::string syntax = explicitVr ? "1.2.840.10008.1.2.1" : "1.2.840.10008.1.2";
    const std::string problem = colourCodingProblem(walk.photometric, syntax, false);
    if (!problem.empty()) failLoad(path, problem);
    return DicomStructure::Plausible;
  }
  const size_t metaEnd = walk.run(132, true, false, true);
  if (!walk.problem.empty()) failLoad(path, "corrupt DICOM meta header: " + walk.problem);
  // GDCM trusts the meta header's group length (0002,0000) and asserts when it lies.
  if (metaEnd >= 144 && std::memcmp(&bytes[132], "\x02\x00\x00\x00UL\x04\x00", 8) == 0 &&
      readUnsigned(&bytes[140], 4, false) != metaEnd - 144)
    failLoad(path, "corrupt DICOM meta header: its group length is " +
                       std::to_string(readUnsigned(&bytes[140], 4, false)) + ", its elements " +
                       std::to_string(metaEnd - 144) + " bytes");
  const std::string syntax = transferSyntax(bytes, 132, metaEnd);
  if (syntax.empty()) failLoad(path, "DICOM meta header without a transfer syntax");
  if (syntax == "1.2.840.10008.1.2.1.99") {
    // GDCM inflates the data set and reads it as explicit little endian, asserting and
    // allocating by its lengths as in any other: the inflated bytes are walked the same way.
    if (bytes.size() - metaEnd < 2) failLoad(path, "no data set after the DICOM meta header");
    const std::vector<uint8_t> inflated =
        inflateDicomDataSet(path, &bytes[metaEnd], bytes.size() - metaEnd);
    if (inflated.size() < 8) failLoad(path, "no data set in the deflated DICOM data");
    Walk inner{inflated, {}, {}};
    inner.run(0, true, false, false);
    if (!inner.problem.empty())
      failLoad(path, "corrupt or truncated DICOM data (deflated; inflated): " + inner.problem);
    checkDoseGrid(path, walk.sopClass, inner);
    const std::string problem = colourCodingProblem(inner.photometric, syntax, false);
    if (!problem.empty()) failLoad(path, problem);
    return DicomStructure::Plausible;
  }
  const bool explicitVr = syntax != "1.2.840.10008.1.2";
  const bool bigEndian = syntax == "1.2.840.10008.1.2.2";
  if (bytes.size() - metaEnd < 8) failLoad(path, "no data set after the DICOM meta header");
  walk.jpeg = isJpegTransferSyntax(syntax);
  walk.jpeg2000 = isJpeg2000TransferSyntax(syntax);
  walk.jpegLs = isJpegLsTransferSyntax(syntax);
  walk.zeroElements = !bigEndian;
  walk.run(metaEnd, explicitVr, bigEndian, false);
  if (!walk.problem.empty()) failLoad(path, "corrupt or truncated DICOM data: " + walk.problem);
  checkDoseGrid(path, walk.sopClass, walk);
  // GDCM's pixmap reader already decodes RLE to tell whether the image is lossy, and asserts
  // when a colour space's size disagrees with the codec's (found with YBR_FULL_422 in RLE).
  const bool encapsulated = syntax != "1.2.840.10008.1.2" && syntax != "1.2.840.10008.1.2.1" &&
                            syntax != "1.2.840.10008.1.2.2";
  const std::string problem = colourCodingProblem(walk.photometric, syntax, encapsulated);
  if (!problem.empty()) failLoad(path, problem);
  return DicomStructure::Plausible;
}

}  // namespace ewa

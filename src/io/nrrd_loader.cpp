// NRRD data reading: attached or detached, one or many data files, raw, compressed or text.
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "io/byte_order.h"
#include "io/decompress.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/nrrd_header.h"
#include "io/region_read.h"
#include "io/text_numbers.h"

namespace ewa {

namespace {

struct DataPiece {
  std::string file;
  uint64_t start = 0;  // first byte after the header (attached) or 0 (detached)
};

// Bytes each data file holds: the first `subdim` axes, or an even share of the whole.
uint64_t bytesPerFile(const std::string& path, const NrrdHeader& h, uint64_t total, size_t files) {
  if (h.subdim > 0) {
    uint64_t per = fileScalarSize(h.layout.type);
    for (int a = 0; a < h.subdim; ++a) per *= static_cast<uint64_t>(h.sizes[size_t(a)]);
    if (per * files != total) {  // no overflow: per <= total and files <= total / per is checked
      failLoad(path, std::to_string(files) + " data files of subdimension " +
                         std::to_string(h.subdim) + " do not match the sizes");
    }
    return per;
  }
  if (total % files != 0 || total / files % fileScalarSize(h.layout.type) != 0) {
    failLoad(path, "the data cannot be split evenly over " + std::to_string(files) + " data files");
  }
  return total / files;
}

// Offset of the raw data in `piece`, after line and byte skips, checked against the file size.
uint64_t rawDataOffset(const NrrdHeader& h, const DataPiece& piece, uint64_t bytes) {
  const uint64_t afterLines = skipLines(piece.file, piece.start, h.lineSkip);
  const uint64_t size = regularFileSize(piece.file);
  if (h.byteSkip == -1) {
    // "byte skip: -1": the data are the last bytes of the file.
    if (size < bytes || size - bytes < afterLines) {
      failLoad(piece.file, "file has " + std::to_string(size) + " bytes, too few for the " +
                               std::to_string(bytes) + " bytes of data");
    }
    return size - bytes;
  }
  const uint64_t offset = afterLines + static_cast<uint64_t>(h.byteSkip);
  if (offset < afterLines || offset > size || size - offset < bytes) {
    failLoad(piece.file, "file has " + std::to_string(size) + " bytes, but the data needs " +
                             std::to_string(bytes) + " bytes at offset " + std::to_string(offset) +
                             " (truncated file or wrong sizes?)");
  }
  return offset;
}

std::vector<uint8_t> readRaw(const NrrdHeader& h, const std::vector<DataPiece>& pieces,
                             uint64_t perFile, uint64_t total) {
  // Check every file before allocating the whole volume.
  std::vector<uint64_t> offsets;
  for (const DataPiece& piece : pieces) offsets.push_back(rawDataOffset(h, piece, perFile));
  std::vector<uint8_t> bytes(static_cast<size_t>(total));
  for (size_t i = 0; i < pieces.size(); ++i) {
    readFileRangeInto(pieces[i].file, offsets[i], perFile, bytes.data() + i * perFile);
  }
  return bytes;
}

// One data file's bytes, decoded. The line skip counts lines of the file; the byte skip counts
// decompressed bytes in compressed data and characters in text. Text numbers come out in
// native byte order, hex bytes in the header's.
std::vector<uint8_t> readEncoded(const NrrdHeader& h, const DataPiece& piece, uint64_t bytes) {
  const uint64_t offset = skipLines(piece.file, piece.start, h.lineSkip);
  const auto skip = static_cast<uint64_t>(h.byteSkip);  // not -1: only raw data allow it
  if (skip > UINT64_MAX - bytes - offset) failLoad(piece.file, "byte skip is too large");
  switch (h.encoding) {
    case NrrdEncoding::Ascii: {
      const uint64_t count = bytes / fileScalarSize(h.layout.type);
      return encodeValues(readTextNumbers(piece.file, offset + skip, count, "ASCII data"),
                          h.layout.type);
    }
    case NrrdEncoding::Hex:
      return readHexBytes(piece.file, offset + skip, bytes, "hex data");
    default:
      break;
  }
  const bool gzip = h.encoding == NrrdEncoding::Gzip;
  const char* what = gzip ? "gzip data" : "bzip2 data";
  const std::vector<uint8_t> packed =
      readFileRange(piece.file, offset, regularFileSize(piece.file) - offset, what);
  std::vector<uint8_t> data =
      gzip ? inflateExact(piece.file, packed.data(), packed.size(), skip + bytes, what)
           : bunzip2Exact(piece.file, packed.data(), packed.size(), skip + bytes, what);
  data.erase(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(skip));
  return data;
}

std::vector<uint8_t> readDecoded(const NrrdHeader& h, const std::vector<DataPiece>& pieces,
                                 uint64_t perFile) {
  if (pieces.size() == 1) return readEncoded(h, pieces[0], perFile);  // the usual case: no copy
  std::vector<uint8_t> bytes;
  for (const DataPiece& piece : pieces) {
    const std::vector<uint8_t> data = readEncoded(h, piece, perFile);
    bytes.insert(bytes.end(), data.begin(), data.end());
  }
  return bytes;
}

// Which volume of a 4D file's extra axis to open (--frame, or --channel for colour and vector
// kinds), checked against its size; the layout says which of how many, the notes why.
int64_t pickVolume(const std::string& path, const NrrdHeader& h, int frame, int channel,
                   VolumeLayout& layout) {
  const NrrdExtraAxis& e = h.extra;
  const std::string kind = e.kind.empty() ? std::string() : " (kind " + e.kind + ")";
  if (e.channels) {
    checkChannel(path, channel, e.size);
    layout.channel = channel;
    layout.channelCount = int(std::min<int64_t>(e.size, std::numeric_limits<int>::max()));
    layout.notes.push_back("4D NRRD of " + std::to_string(e.size) + " channels" + kind +
                           "; showing channel " + std::to_string(channel) +
                           " (--channel N picks another)");
    return channel;
  }
  checkFrame(path, frame, e.size);
  layout.frame = frame;
  layout.frameCount = int(std::min<int64_t>(e.size, std::numeric_limits<int>::max()));
  layout.notes.push_back("4D NRRD of " + std::to_string(e.size) + " frames" + kind +
                         "; showing frame " + std::to_string(frame) + " (--frame N picks another)");
  return frame;
}

}  // namespace

Volume loadNrrd(const std::string& path, int frame, int channel, DataFileScope scope) {
  const NrrdHeader h = parseNrrdHeader(path);
  VolumeLayout layout = h.layout;
  for (const std::string& file : h.dataFiles) checkDataFileScope(path, file, scope);
  layout.sourceFiles = h.dataFiles;
  const uint64_t volumeBytes = dataByteCount(path, layout.dims, layout.type);
  int64_t index = 0;
  uint64_t total = volumeBytes;
  if (h.extra.axis >= 0) {
    index = pickVolume(path, h, frame, channel, layout);
    if (h.extra.size <= 0 || __builtin_mul_overflow(volumeBytes, uint64_t(h.extra.size), &total))
      failLoad(path, "4D sizes overflow 64-bit byte counts");
  }
  std::vector<DataPiece> pieces;
  if (h.dataFiles.empty()) {
    pieces.push_back({path, h.attachedOffset});
  } else {
    if (h.dataFiles.size() > total) failLoad(path, "more data files than data");
    for (const std::string& f : h.dataFiles) pieces.push_back({f, 0});
  }
  const uint64_t perFile = bytesPerFile(path, h, total, pieces.size());
  const bool raw = h.encoding == NrrdEncoding::Raw;
  if (h.extra.axis == 3 && raw && pieces.size() == 1) {
    // Time points last in one raw file: only the one asked for is read.
    const uint64_t offset = rawDataOffset(h, pieces[0], total);
    return makeVolume(path, layout,
                      readFileRange(pieces[0].file, offset + uint64_t(index) * volumeBytes,
                                    volumeBytes, "NRRD frame"));
  }
  if (h.extra.axis >= 0) checkAllocation(path, total, "4D NRRD data");
  std::vector<uint8_t> bytes =
      raw ? readRaw(h, pieces, perFile, total) : readDecoded(h, pieces, perFile);
  if (h.encoding == NrrdEncoding::Ascii) layout.bigEndian = hostIsBigEndian();
  if (h.extra.axis >= 0)
    bytes = nrrdVolumeOf(bytes, h.extra, index, volumeBytes / fileScalarSize(layout.type),
                         fileScalarSize(layout.type));
  return makeVolume(path, layout, std::move(bytes));
}

std::optional<RawPlacement> nrrdRawPlacement(const std::string& path, DataFileScope scope) {
  const NrrdHeader h = parseNrrdHeader(path);
  if (h.encoding != NrrdEncoding::Raw || h.extra.axis >= 0 || h.dataFiles.size() > 1)
    return std::nullopt;
  for (const std::string& file : h.dataFiles) checkDataFileScope(path, file, scope);
  const DataPiece piece =
      h.dataFiles.empty() ? DataPiece{path, h.attachedOffset} : DataPiece{h.dataFiles[0], 0};
  RawPlacement p;
  p.layout = h.layout;
  p.layout.sourceFiles = h.dataFiles;
  p.file = piece.file;
  p.offset = rawDataOffset(h, piece, wholeDataBytes(path, h.layout.dims, h.layout.type));
  return p;
}

}  // namespace ewa

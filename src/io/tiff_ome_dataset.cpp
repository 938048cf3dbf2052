// OME-TIFF datasets over several files: each slice read from the file and page its TiffData names.
#include "io/tiff_ome_dataset.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <utility>

#include "core/parallel_chunks.h"
#include "io/load_failure.h"

namespace ewa {

int64_t tiffPageCount(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return 0;
  try {
    TiffFile tiff(file);
    return int64_t(TIFFNumberOfDirectories(tiff.get()));
  } catch (const LoadError&) {
    return 0;
  }
}

std::vector<uint8_t> readOmeDataset(const std::string& path, const std::string& xmlFile,
                                    const TiffPlaneOrder& order, const PageFormat& format,
                                    int64_t planeChannel, int sample, int64_t frame,
                                    VolumeLayout& layout) {
  const auto sources = omePlaneSources(xmlFile, order, planeChannel, frame, &tiffPageCount);
  const int64_t slices = std::max<int64_t>(order.slices, 1);
  for (int64_t z = 0; z < slices; ++z)  // at most one past the slices found
    if (!sources.count(z))
      failLoad(path, "slice " + std::to_string(z) + " of channel " + std::to_string(planeChannel) +
                         ", time point " + std::to_string(frame) +
                         " is in none of the OME-TIFF dataset's files");
  const size_t pageBytes = size_t(format.width) * format.height * fileScalarSize(layout.type);
  dataByteCount(xmlFile, {int64_t(format.width), int64_t(format.height), slices}, layout.type);
  std::vector<uint8_t> bytes(pageBytes * size_t(slices));
  const std::vector<std::pair<int64_t, TiffPlaneSource>> list(sources.begin(), sources.end());
  // Each chunk of slices opens its files itself and decodes its pages on its own core.
  parallelChunks(list.size(), 1, 0, [&](size_t first, size_t last, size_t) {
    std::unique_ptr<TiffFile> open;
    for (size_t n = first; n < last; ++n) {
      const auto& [z, source] = list[n];
      if (!open || open->path() != source.file) open = std::make_unique<TiffFile>(source.file);
      if (!TIFFSetDirectory(open->get(), tdir_t(source.ifd)))
        open->fail("has no page " + std::to_string(source.ifd));
      const PageFormat f = pageFormat(*open);
      if (!(f == format))
        open->fail("page " + std::to_string(source.ifd) + " is " + f.text() + ", the first " +
                   format.text() + ": all pages must agree");
      readPage(*open, f, sample, bytes.data() + size_t(z) * pageBytes);
    }
  });
  std::set<std::string> files;
  for (const auto& slice : list) files.insert(slice.second.file);
  layout.notes.push_back("an OME-TIFF dataset: " + std::to_string(slices) + " slices from " +
                         std::to_string(files.size()) + " files");
  return bytes;
}

}  // namespace ewa

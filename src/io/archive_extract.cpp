// Unpacks archives with libarchive into a private scratch folder, bounded and confined to it.
#include "io/archive_extract.h"

#include <archive.h>
#include <archive_entry.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "io/file_listing.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/scratch_cleanup.h"

namespace ewa {

namespace fs = std::filesystem;

const std::vector<std::string>& archiveFileExtensions() {
  static const std::vector<std::string> kExtensions = {
      ".zip", ".tar", ".tgz", ".tar.gz", ".tar.bz2", ".tbz2", ".tar.xz", ".txz", ".tar.zst", ".7z"};
  return kExtensions;
}

bool isArchiveName(const std::string& path) {
  return hasExtension(path, archiveFileExtensions());
}

ExtractedArchive::ExtractedArchive(std::string folder) : folder_(std::move(folder)) {
  if (!folder_.empty()) registerScratchFolder(folder_);
}

ExtractedArchive::ExtractedArchive(ExtractedArchive&& other) noexcept
    : files(other.files),
      bytes(other.bytes),
      skipped(other.skipped),
      folder_(std::move(other.folder_)) {
  other.folder_.clear();
}

ExtractedArchive& ExtractedArchive::operator=(ExtractedArchive&& other) noexcept {
  if (this != &other) {
    remove();
    folder_ = std::move(other.folder_);
    other.folder_.clear();
    files = other.files;
    bytes = other.bytes;
    skipped = other.skipped;
  }
  return *this;
}

ExtractedArchive::~ExtractedArchive() {
  remove();
}

void ExtractedArchive::remove() {
  if (folder_.empty()) return;
  std::error_code ec;
  fs::remove_all(folder_, ec);
  unregisterScratchFolder(folder_);
  folder_.clear();
}

std::string ExtractedArchive::relative(const std::string& message) const {
  if (folder_.empty()) return message;  // moved from
  std::string out = message;
  for (const std::string& from : {folder_ + "/", folder_ + ": ", folder_}) {
    for (size_t at = out.find(from); !from.empty() && at != std::string::npos;
         at = out.find(from, at))
      out.erase(at, from.size());
  }
  return out;
}

namespace {

using ArchivePtr = std::unique_ptr<archive, decltype(&archive_read_free)>;

// The entry's name as a path below the folder, or empty when it would leave it (absolute, "..")
// or is a macOS resource fork. Zips from Windows may separate with backslashes.
fs::path safeRelativeName(const char* name) {
  if (!name) return {};
  fs::path out;
  std::string part;
  const std::string text = std::string(name) + "/";
  if (text[0] == '/' || text[0] == '\\') return {};
  for (const char c : text) {
    if (c != '/' && c != '\\') {
      part += c;
      continue;
    }
    if (part == "..") return {};
    if (!part.empty() && part != ".") {
      if (out.empty() && part == "__MACOSX") return {};
      out /= part;
    }
    part.clear();
  }
  if (out.filename().string().rfind("._", 0) == 0) return {};
  return out;
}

constexpr const char* kScratchPrefix = "ewaview-archive-";

// Removes the scratch folders of ewaview processes that are gone (killed before they could),
// told by the process id in the folder's name.
void removeStaleScratchFolders(const fs::path& temp) {
  std::error_code ec;
  for (fs::directory_iterator it(temp, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kScratchPrefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + std::strlen(kScratchPrefix), nullptr, 10);
    if (pid <= 0 || pid == long(getpid())) continue;
    if (kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to ask
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

fs::path makeScratchFolder(const std::string& path) {
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  if (ec) failLoad(path, "no temporary folder to unpack into (" + ec.message() + ")");
  removeStaleScratchFolders(temp);
  std::string pattern = (temp / (kScratchPrefix + std::to_string(getpid()) + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data()))
    failLoad(path, "cannot make a folder to unpack into under " + temp.string());
  return pattern;
}

[[noreturn]] void failArchive(const std::string& path, archive* a, const std::string& what) {
  const char* why = archive_error_string(a);
  failLoad(path, what + (why ? " (" + oneLine(why) + ")" : std::string()));
}

std::string sizeText(uint64_t bytes) {
  return bytes >> 20 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

// What bounds an archive's unpacked size, and how to say it.
struct UnpackBudget {
  uint64_t bytes = 0;
  std::string why;
  uint64_t ratioFloor = 0, maxRatio = 0;  // the running ratio's bound (ArchiveLimits)

  [[noreturn]] void exceeded(const std::string& path) const {
    failLoad(path, "unpacks to more than " + sizeText(bytes) + " (" + why + ")");
  }
  // Past the floor, `unpacked` bytes from `read` compressed ones at most maxRatio to 1.
  void checkRatio(const std::string& path, uint64_t unpacked, uint64_t read) const {
    if (maxRatio == 0 || unpacked <= ratioFloor || unpacked / maxRatio <= read) return;
    failLoad(path, "unpacks to more than " + std::to_string(maxRatio) + " times the " +
                       sizeText(read) + " read of it (" + sizeText(unpacked) +
                       " so far): an archive bomb? unpack it yourself if it is not");
  }
};

UnpackBudget unpackBudget(const std::string& path, const fs::path& root,
                          const ArchiveLimits& limits) {
  UnpackBudget budget{limits.maxBytes, "the limit set", limits.ratioFloorBytes, limits.maxRatio};
  if (budget.bytes == 0) {
    std::error_code ec;
    const fs::space_info space = fs::space(root, ec);
    budget.bytes = usableMemoryBytes();
    budget.why = "this machine's memory";
    if (!ec && space.available < budget.bytes) {
      budget.bytes = space.available;
      budget.why = "the scratch disk's free space";
    }
  }
  std::error_code ec;
  const uint64_t packed = fs::file_size(path, ec);
  if (!ec && limits.maxRatio > 0) {
    const uint64_t byRatio =
        packed > UINT64_MAX / limits.maxRatio ? UINT64_MAX : packed * limits.maxRatio;
    const uint64_t cap = std::max(limits.ratioFloorBytes, byRatio);
    if (cap < budget.bytes) {
      budget.bytes = cap;
      budget.why = std::to_string(limits.maxRatio) + " times the archive's " + sizeText(packed) +
                   ": an archive bomb? unpack it yourself if it is not";
    }
  }
  return budget;
}

// Copies the current entry's data to `target`; `used` bytes are written already, of `budget`.
uint64_t writeEntry(const std::string& path, archive* a, const fs::path& target,
                    const std::string& name, uint64_t used, const UnpackBudget& budget) {
  std::unique_ptr<FILE, decltype(&std::fclose)> out(std::fopen(target.c_str(), "wb"), &std::fclose);
  if (!out) failLoad(path, "cannot unpack " + quoteText(name) + " to the scratch folder");
  std::vector<char> buffer(1 << 18);
  uint64_t written = 0;
  for (;;) {
    const la_ssize_t got = archive_read_data(a, buffer.data(), buffer.size());
    if (got == 0) break;
    if (got < 0) failArchive(path, a, "a damaged archive: cannot read " + quoteText(name));
    written += uint64_t(got);
    if (written > budget.bytes - used) budget.exceeded(path);
    budget.checkRatio(path, used + written,
                      uint64_t(std::max<la_int64_t>(archive_filter_bytes(a, -1), 0)));
    if (std::fwrite(buffer.data(), 1, size_t(got), out.get()) != size_t(got))
      failLoad(path, "cannot unpack " + quoteText(name) + " (is the scratch disk full?)");
  }
  if (std::fflush(out.get()) != 0) failLoad(path, "cannot unpack " + quoteText(name));
  return written;
}

}  // namespace

ExtractedArchive extractArchive(const std::string& path, const ArchiveLimits& limits) {
  ArchivePtr reader(archive_read_new(), &archive_read_free);
  if (!reader) failLoad(path, "out of memory");
  archive* a = reader.get();
  // Named filters, not "all": that one also runs external programs for formats it lacks.
  archive_read_support_filter_gzip(a);
  archive_read_support_filter_bzip2(a);
  archive_read_support_filter_xz(a);
  archive_read_support_filter_lzma(a);
  archive_read_support_filter_zstd(a);
  // The formats volumes come in; not "all" (ISO images, RAR, ... are no use and more to trust).
  archive_read_support_format_zip(a);
  archive_read_support_format_tar(a);
  archive_read_support_format_cpio(a);
  archive_read_support_format_7zip(a);
  if (archive_read_open_filename(a, path.c_str(), 1 << 16) != ARCHIVE_OK)
    failArchive(path, a, "not an archive ewaview can read");

  ExtractedArchive unpacked(makeScratchFolder(path).string());
  const fs::path root = unpacked.folder();
  const UnpackBudget budget = unpackBudget(path, root, limits);
  for (;;) {
    archive_entry* entry = nullptr;
    const int status = archive_read_next_header(a, &entry);
    if (status == ARCHIVE_EOF) break;
    if (status < ARCHIVE_WARN) failArchive(path, a, "a damaged archive");
    const fs::path name = safeRelativeName(archive_entry_pathname(entry));
    if (archive_entry_filetype(entry) != AE_IFREG || name.empty()) {
      if (archive_entry_filetype(entry) != AE_IFDIR) ++unpacked.skipped;
      continue;
    }
    if (archive_entry_is_encrypted(entry))
      failLoad(path, quoteText(name.string()) + " is encrypted (unpack it with its password)");
    // A declared size past the budget is refused before a byte of it is written.
    if (archive_entry_size_is_set(entry) && archive_entry_size(entry) > 0 &&
        uint64_t(archive_entry_size(entry)) > budget.bytes - unpacked.bytes)
      budget.exceeded(path);
    if (unpacked.files >= limits.maxFiles)
      failLoad(path, "holds more than " + std::to_string(limits.maxFiles) + " files");
    std::error_code ec;
    fs::create_directories((root / name).parent_path(), ec);
    if (ec) failLoad(path, "cannot unpack " + quoteText(name.string()) + " (" + ec.message() + ")");
    unpacked.bytes += writeEntry(path, a, root / name, name.string(), unpacked.bytes, budget);
    ++unpacked.files;
  }
  return unpacked;
}

std::string archiveVolumePath(const ExtractedArchive& archive, const std::string& path) {
  if (archive.files == 0)
    failLoad(path, "holds no files" + (archive.skipped ? " but " + std::to_string(archive.skipped) +
                                                             " links or names outside it"
                                                       : std::string()));
  static const std::vector<std::string> kHeaders = {
      ".nrrd", ".nhdr", ".mhd", ".mha",     ".dat", ".vti",  ".vtk", ".nii",  ".nii.gz",
      ".hdr",  ".slc",  ".ome", ".ome.xml", ".mrc", ".mrcs", ".map", ".ccp4", ".rec"};
  // One walk: the volume files with headers, and the other files, looked into only when there
  // are none.
  std::vector<std::string> volumes, others;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(archive.folder(), ec), end; !ec && it != end;
       it.increment(ec))
    if (it->is_regular_file(ec))
      (hasExtension(it->path().string(), kHeaders) ? volumes : others)
          .push_back(it->path().string());
  if (volumes.size() == 1) return volumes.front();
  if (volumes.size() > 1) {
    std::sort(volumes.begin(), volumes.end());
    std::string names;
    for (size_t i = 0; i < std::min<size_t>(volumes.size(), 3); ++i)
      names += (i ? ", " : "") + archive.relative(volumes[i]);
    failLoad(path, "holds " + std::to_string(volumes.size()) + " volume files (" + names +
                       (volumes.size() > 3 ? ", ..." : "") + "): unpack it and open one");
  }
  // A DICOM series or a stack of TIFF or other images, often inside a folder of its own.
  const bool images = std::any_of(others.begin(), others.end(), [](const std::string& file) {
    return hasExtension(file, {".tif", ".tiff"}) || hasExtension(file, sliceImageExtensions()) ||
           looksLikeDicom(file);
  });
  if (!images)
    failLoad(path, "holds no volume file, DICOM image, TIFF file or slice image (" +
                       std::to_string(archive.files) + " other files)");
  fs::path folder = archive.folder();
  for (;;) {
    fs::directory_iterator it(folder, ec), end;
    if (ec || it == end) break;
    const fs::path only = it->path();
    const bool lone = it->is_directory(ec) && it.increment(ec) == end && !ec;
    if (!lone) break;
    folder = only;
  }
  return folder.string();
}

}  // namespace ewa

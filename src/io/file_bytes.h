// Reading whole files, byte ranges and header prefixes with size checks done before allocating.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ewa {

// Size of the regular file at `path`. Throws LoadError for a missing or unreadable file, a
// directory, or anything else that is not a regular file (a FIFO could block forever).
uint64_t regularFileSize(const std::string& path);

// Reads `length` bytes at `offset`, after checking that the file holds them, so a header
// cannot make us allocate for data that is not there. `what` names the bytes in messages.
std::vector<uint8_t> readFileRange(const std::string& path, uint64_t offset, uint64_t length,
                                   const std::string& what = "data");

// As readFileRange, into `out`, which must have room for `length` bytes.
void readFileRangeInto(const std::string& path, uint64_t offset, uint64_t length, uint8_t* out,
                       const std::string& what = "data");

// Reads the start of the file as text: small at first, growing until `isComplete(text)`, the
// end of the file or `limit` bytes. The caller checks whether its header end was found.
std::string readFilePrefix(const std::string& path, uint64_t limit,
                           const std::function<bool(std::string_view)>& isComplete);

// Offset just past `lines` newline characters counted from `offset` (NRRD "line skip").
uint64_t skipLines(const std::string& path, uint64_t offset, int64_t lines);

// A data file name from a header, relative to the header's folder unless absolute.
std::string siblingPath(const std::string& headerPath, const std::string& name);

// Where a detached header (MetaImage, NRRD, .dat) may name its data files.
enum class DataFileScope {
  HeaderFolder,  // the header's folder or below, links resolved (the default)
  Anywhere       // any file the user can read (--allow-outside-data)
};

// Throws LoadError naming `headerPath` when `dataPath` (siblingPath's result) lies outside the
// header's folder and `scope` is HeaderFolder: a header from elsewhere must not make ewaview
// read, show or save files such as /etc/shadow or ../../secret.
void checkDataFileScope(const std::string& headerPath, const std::string& dataPath,
                        DataFileScope scope);

// Random access to a block of bytes (part of a file or a decoded buffer), bounds-checked.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual uint64_t size() const = 0;
  // Bytes [offset, offset + length); throws LoadError naming `what` when they are not all there.
  virtual std::vector<uint8_t> read(uint64_t offset, uint64_t length,
                                    const std::string& what) const = 0;
};

// The bytes of a file from `base` to its end.
class FileSource : public ByteSource {
 public:
  FileSource(std::string path, uint64_t base);
  uint64_t size() const override { return size_; }
  std::vector<uint8_t> read(uint64_t offset, uint64_t length,
                            const std::string& what) const override;

 private:
  std::string path_;
  uint64_t base_ = 0;
  uint64_t size_ = 0;
};

// Bytes already in memory; `path` is only for messages.
class MemorySource : public ByteSource {
 public:
  MemorySource(std::string path, std::vector<uint8_t> bytes)
      : path_(std::move(path)), bytes_(std::move(bytes)) {}
  uint64_t size() const override { return bytes_.size(); }
  std::vector<uint8_t> read(uint64_t offset, uint64_t length,
                            const std::string& what) const override;

 private:
  std::string path_;
  std::vector<uint8_t> bytes_;
};

}  // namespace ewa

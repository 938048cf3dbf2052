// Helpers for the loader tests: scratch folder, byte builders, zlib/gzip/bzip2, LoadError checks.
#pragma once

#include <bzlib.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "io/volume_loader.h"

namespace ewa::testing {

// A fresh folder under the system temp folder, removed with its contents at the end.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "ewa_loader_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path(const std::string& name) const { return (path_ / name).string(); }
  // Writes `bytes` to `name` and returns the full path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = path(name);
    // Replace rather than truncate: ext4 flushes truncated-and-rewritten files to disk on close.
    std::error_code ec;
    std::filesystem::remove(p, ec);
    std::ofstream out(p, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + p);
    return p;
  }

 private:
  std::filesystem::path path_;
};

// The bytes of `values` in the given byte order.
template <typename T>
std::string bytesOf(const std::vector<T>& values, bool bigEndian = false) {
  std::string out(values.size() * sizeof(T), '\0');
  for (size_t i = 0; i < values.size(); ++i) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &values[i], sizeof(T));
    const uint16_t probe = 1;
    const bool hostBig = *reinterpret_cast<const unsigned char*>(&probe) == 0;
    for (size_t k = 0; k < sizeof(T); ++k) {
      out[i * sizeof(T) + k] =
          static_cast<char>(hostBig == bigEndian ? b[k] : b[sizeof(T) - 1 - k]);
    }
  }
  return out;
}

// zlib (windowBits 15) or gzip (15 + 16) compression of `data`.
inline std::string compressBytes(const std::string& data, bool gzip) {
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, gzip ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("deflateInit2 failed");
  std::string out(deflateBound(&zs, static_cast<uLong>(data.size())) + 64, '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  const int ret = deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  if (ret != Z_STREAM_END) throw std::runtime_error("deflate failed");
  return out;
}
inline std::string gzipBytes(const std::string& data) {
  return compressBytes(data, true);
}
inline std::string zlibBytes(const std::string& data) {
  return compressBytes(data, false);
}

// One bzip2 stream of `data`.
inline std::string bzip2Bytes(const std::string& data) {
  auto size = static_cast<unsigned int>(data.size() + data.size() / 100 + 700);
  std::string out(size, '\0');
  if (BZ2_bzBuffToBuffCompress(out.data(), &size, const_cast<char*>(data.data()),
                               static_cast<unsigned int>(data.size()), 9, 0, 0) != BZ_OK)
    throw std::runtime_error("BZ2_bzBuffToBuffCompress failed");
  out.resize(size);
  return out;
}

// Little-endian (or big-endian) unsigned integer of `width` bytes.
inline std::string uintBytes(uint64_t v, int width, bool bigEndian = false) {
  std::string out(static_cast<size_t>(width), '\0');
  for (int i = 0; i < width; ++i) {
    out[static_cast<size_t>(bigEndian ? width - 1 - i : i)] =
        static_cast<char>((v >> (8 * i)) & 0xff);
  }
  return out;
}

// Expects `load` to throw a LoadError whose one-line message starts with "<path>: " and
// contains `fragment` (when not empty).
// `fragment` names the expected problem: a test that accepts any message would pass a loader
// that fails for the wrong reason.
inline void expectLoadError(const std::function<void()>& load, const std::string& path,
                            const std::string& fragment) {
  try {
    load();
    ADD_FAILURE() << "no LoadError for " << path;
  } catch (const LoadError& e) {
    const std::string msg = e.what();
    // EWA_SHOW_LOAD_ERRORS=1 prints every message, to review their wording.
    if (std::getenv("EWA_SHOW_LOAD_ERRORS")) std::printf("  LoadError: %s\n", msg.c_str());
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << "message does not start with the path: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
    EXPECT_FALSE(fragment.empty()) << "the test must name the expected problem";
    EXPECT_NE(msg.find(fragment), std::string::npos)
        << "message lacks '" << fragment << "': " << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a LoadError for " << path << ": " << e.what();
  }
}

inline void expectVolumeLoadError(const std::string& path, const std::string& fragment) {
  expectLoadError([&] { loadVolume(path); }, path, fragment);
}

// A file's bytes (to cut or patch it).
inline std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Whether one of `v`'s notes holds `text`.
inline bool hasNoteWith(const Volume& v, const std::string& text) {
  for (const std::string& note : v.notes())
    if (note.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace ewa::testing

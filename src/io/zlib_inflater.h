// An inflating zlib stream that is ended however its owner leaves (one RAII type for every
// inflating reader: compressed volume data, deflated DICOM data sets).
#pragma once

#include <zlib.h>

namespace ewa {

class ZlibInflater {
 public:
  // zlib's windowBits: 15 + 32 for a zlib or gzip stream told apart by its header, -15 for raw
  // deflate (DICOM's deflated transfer syntax).
  explicit ZlibInflater(int windowBits) { ok_ = inflateInit2(&zs_, windowBits) == Z_OK; }
  ~ZlibInflater() {
    if (ok_) inflateEnd(&zs_);
  }
  ZlibInflater(const ZlibInflater&) = delete;
  ZlibInflater& operator=(const ZlibInflater&) = delete;
  bool ok() const { return ok_; }
  z_stream& stream() { return zs_; }

 private:
  z_stream zs_{};
  bool ok_ = false;
};

}  // namespace ewa

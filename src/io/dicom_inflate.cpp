// inflateDicomDataSet: zlib's raw inflate of a deflated DICOM data set, bounded in size.
#include "io/dicom_inflate.h"

#include <zlib.h>

#include <algorithm>
#include <climits>

#include "io/load_failure.h"
#include "io/memory_limit.h"
#include "io/zlib_inflater.h"

namespace ewa {

uint64_t dicomInflateLimit(uint64_t deflatedBytes) {
  const uint64_t byRatio = deflatedBytes > kDicomInflateCap / kDicomInflateRatio
                               ? kDicomInflateCap
                               : deflatedBytes * kDicomInflateRatio;
  return std::min(kDicomInflateCap, std::max(kDicomInflateFloor, byRatio));
}

std::vector<uint8_t> inflateDicomDataSet(const std::string& path, const uint8_t* data,
                                         size_t size) {
  const std::string prefix = "the deflated DICOM data set ";
  const uint64_t limit = dicomInflateLimit(size);
  ZlibInflater inflater(-MAX_WBITS);  // raw deflate
  if (!inflater.ok()) failLoad(path, prefix + "cannot be read: zlib does not start");
  z_stream& zs = inflater.stream();
  std::vector<uint8_t> out;
  size_t consumed = 0;
  int ret = Z_OK;
  while (ret != Z_STREAM_END) {
    if (out.size() == limit)
      failLoad(path, prefix + "inflates to more than " + std::to_string(limit) + " bytes (" +
                         std::to_string(size) + " deflated): a deflate bomb?");
    // Doubling (from 1 MiB) up to the limit: memory follows what the stream really yields.
    const size_t grown = size_t(
        std::min<uint64_t>(limit, std::max<uint64_t>(uint64_t(1) << 20, uint64_t(out.size()) * 2)));
    checkAllocation(path, grown, "inflated DICOM data set");
    const size_t have = out.size();
    out.resize(grown);
    zs.next_out = out.data() + have;
    zs.avail_out = uInt(std::min<size_t>(grown - have, UINT_MAX));
    while (zs.avail_out > 0) {
      if (zs.avail_in == 0 && consumed < size) {
        const size_t piece = std::min<size_t>(size - consumed, UINT_MAX);
        zs.next_in = const_cast<Bytef*>(data + consumed);
        zs.avail_in = uInt(piece);
        consumed += piece;
      }
      const uInt before = zs.avail_out;
      ret = inflate(&zs, Z_NO_FLUSH);
      if (ret == Z_STREAM_END) break;
      if (ret == Z_NEED_DICT || ret == Z_DATA_ERROR || ret == Z_MEM_ERROR)
        failLoad(path, prefix + "is corrupt (" + (zs.msg ? std::string(zs.msg) : "zlib") + ")");
      if (ret == Z_BUF_ERROR || (zs.avail_in == 0 && consumed == size && zs.avail_out == before))
        failLoad(path, prefix + "is cut short (its deflate stream does not end)");
    }
    out.resize(size_t(zs.next_out - out.data()));
  }
  return out;
}

}  // namespace ewa

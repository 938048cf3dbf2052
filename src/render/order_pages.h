// OrderPages: the CPU slab partition's order list on the GPU, held in pages of a fixed number
// of entries, so that a big list is allocated page by page within a window step's budget.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/buffer.h"

namespace ewa {

// One buffer for the whole list made a 512^3 volume's first refinement hold one UI frame for
// 2 s on llvmpipe: creating a buffer zero-fills all of it (0.6-0.9 GB) before anything is copied.
// Pages are kept between frames (allocating costs far more than copying) and grow as lists do.
class OrderPages {
 public:
  // 1 Mi entries, 4 MiB: made and filled in about 25 ms on llvmpipe here, within a window step's
  // 30 ms budget (16 MiB pages took about 100 ms each).
  static constexpr size_t kDefaultPageEntries = size_t(1) << 20;

  explicit OrderPages(size_t pageEntries = kDefaultPageEntries);

  // Entries a page holds (at least 1); a new size drops the pages.
  void setPageEntries(size_t entries);
  size_t pageEntries() const { return pageEntries_; }

  // Copies `count` entries from `entries` to positions [first, first + count) of a list of
  // `total` entries, making or enlarging the pages they fall in first. A page is made as big as
  // the list needs of it; one enlarged for a longer list gets an eighth to spare (up to a page),
  // so the next views' lists fit.
  void upload(const uint32_t* entries, size_t first, size_t count, size_t total);
  // The page holding list position `entry`; its position in that page is entry % pageEntries().
  const gl::Buffer& page(size_t entry) const { return pages_[entry / pageEntries_]; }

  void clear() { pages_.clear(); }
  size_t pageCount() const { return pages_.size(); }
  // Bytes of GPU memory the pages hold.
  size_t bytes() const;

 private:
  size_t pageEntries_;
  std::vector<gl::Buffer> pages_;
};

}  // namespace ewa

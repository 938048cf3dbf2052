// OrderPages: the CPU slab partition's order list on the GPU, held in pages of up to a fixed
// number of entries laid out along the slabs, so that a big list is allocated page by page
// within a window step's budget.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/buffer.h"

namespace ewa {

// One buffer for the whole list made a 512^3 volume's first refinement hold one UI frame far
// past its budget on llvmpipe: creating a buffer zero-fills all of it (for such a volume, most
// of a gigabyte) before anything is copied. Pages end where slabs do: llvmpipe ends its scene
// (binning) when a draw brings in a new buffer once the scene holds 64 MB of resources, and
// pages that cut through slabs end scenes mid-slab, which lengthened that 512^3 frame. Buffers
// are kept between frames (allocating costs far more than copying) and grow as the pages do.
class OrderPages {
 public:
  // 1 Mi entries, 4 MiB: small enough that making and filling one on llvmpipe fits within a
  // window step's 30 ms budget (a 16 MiB page does not).
  static constexpr size_t kDefaultPageEntries = size_t(1) << 20;

  explicit OrderPages(size_t pageEntries = kDefaultPageEntries);

  // The most entries a page holds (at least 1); a new size drops the buffers.
  void setPageEntries(size_t entries);
  size_t pageEntries() const { return pageEntries_; }

  // Lays out a list of `total` entries: pages of consecutive ranges between `breaks` (list
  // positions in ascending order, each slab's first entry), as many ranges as fit a page
  // together; a range longer than a page is cut into whole pages and the rest.
  void layout(const std::vector<size_t>& breaks, size_t total);
  // Pages of the layout.
  size_t pages() const { return starts_.empty() ? 0 : starts_.size() - 1; }
  // Copies page `i` of the layout from `list` (the whole list), making its buffer, or making
  // it again an eighth larger than needed (up to a page) when it is too small.
  void uploadPage(size_t i, const uint32_t* list);
  void uploadAll(const uint32_t* list);

  // The page holding list position `entry`: its buffer and its first position and length.
  struct Span {
    const gl::Buffer* buffer = nullptr;
    size_t first = 0;
    size_t count = 0;
  };
  Span span(size_t entry) const;

  void clear();
  // Buffers allocated now (a layout with fewer pages keeps the others for later lists).
  size_t bufferCount() const { return buffers_.size(); }
  // Bytes of GPU memory the buffers hold.
  size_t bytes() const;

 private:
  size_t pageEntries_;
  std::vector<size_t> starts_;  // the layout: each page's first position, then the total
  std::vector<gl::Buffer> buffers_;
};

}  // namespace ewa

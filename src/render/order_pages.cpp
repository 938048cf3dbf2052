// OrderPages: the paged GPU store of the CPU slab partition's order list.
#include "render/order_pages.h"

#include <algorithm>

namespace ewa {

OrderPages::OrderPages(size_t pageEntries) : pageEntries_(std::max<size_t>(1, pageEntries)) {}

void OrderPages::setPageEntries(size_t entries) {
  entries = std::max<size_t>(1, entries);
  if (entries == pageEntries_) return;
  pageEntries_ = entries;
  pages_.clear();
}

void OrderPages::upload(const uint32_t* entries, size_t first, size_t count, size_t total) {
  constexpr size_t kEntry = sizeof(uint32_t);
  while (count > 0) {
    const size_t p = first / pageEntries_;
    const size_t inPage = first % pageEntries_;
    const size_t n = std::min(count, pageEntries_ - inPage);
    // What the list needs of this page: all of it, or the list's tail.
    const size_t needed = std::min(pageEntries_, total - p * pageEntries_);
    if (pages_.size() <= p) pages_.resize(p + 1);
    gl::Buffer& page = pages_[p];
    if (size_t(page.size()) < needed * kEntry) {
      const size_t entriesMade =
          page ? std::min(pageEntries_, needed + needed / 8) : needed;  // exact the first time
      page.setData(GLsizeiptr(entriesMade * kEntry), nullptr, GL_STREAM_DRAW);
    }
    page.setSubData(GLintptr(inPage * kEntry), GLsizeiptr(n * kEntry), entries);
    entries += n;
    first += n;
    count -= n;
  }
}

size_t OrderPages::bytes() const {
  size_t sum = 0;
  for (const gl::Buffer& page : pages_) sum += size_t(page.size());
  return sum;
}

}  // namespace ewa

// OrderPages: the paged GPU store of the CPU slab partition's order list.
#include "render/order_pages.h"

#include <algorithm>

namespace ewa {

OrderPages::OrderPages(size_t pageEntries) : pageEntries_(std::max<size_t>(1, pageEntries)) {}

void OrderPages::setPageEntries(size_t entries) {
  entries = std::max<size_t>(1, entries);
  if (entries == pageEntries_) return;
  pageEntries_ = entries;
  clear();
}

void OrderPages::clear() {
  buffers_.clear();
  starts_.clear();
}

void OrderPages::layout(const std::vector<size_t>& breaks, size_t total) {
  starts_.clear();
  if (total == 0) return;
  starts_.push_back(0);
  // Greedy: a page takes whole ranges while they fit; one too long for a page is cut.
  size_t end = 0;  // the current page ends here so far
  auto close = [&](size_t at) {
    if (at > starts_.back()) starts_.push_back(at);
  };
  auto reach = [&](size_t cut) {
    cut = std::min(cut, total);
    if (cut <= end) return;
    if (cut - starts_.back() > pageEntries_) {
      close(end);  // this range does not fit beside the page's ranges
      while (cut - starts_.back() > pageEntries_) close(starts_.back() + pageEntries_);
    }
    end = cut;
  };
  for (size_t cut : breaks) reach(cut);
  reach(total);
  close(total);
}

void OrderPages::uploadPage(size_t i, const uint32_t* list) {
  constexpr size_t kEntry = sizeof(uint32_t);
  const size_t first = starts_[i], count = starts_[i + 1] - starts_[i];
  if (buffers_.size() <= i) buffers_.resize(i + 1);
  gl::Buffer& buffer = buffers_[i];
  if (size_t(buffer.size()) < count * kEntry) {
    const size_t made = buffer ? std::min(pageEntries_, count + count / 8) : count;
    buffer.setData(GLsizeiptr(made * kEntry), nullptr, GL_STREAM_DRAW);
  }
  buffer.setSubData(0, GLsizeiptr(count * kEntry), list + first);
}

void OrderPages::uploadAll(const uint32_t* list) {
  for (size_t i = 0; i < pages(); ++i) uploadPage(i, list);
}

OrderPages::Span OrderPages::span(size_t entry) const {
  // The last page whose first position is at or before `entry`.
  const auto next = std::upper_bound(starts_.begin(), starts_.end() - 1, entry);
  const size_t i = size_t(next - starts_.begin()) - 1;
  return {&buffers_[i], starts_[i], starts_[i + 1] - starts_[i]};
}

size_t OrderPages::bytes() const {
  size_t sum = 0;
  for (const gl::Buffer& buffer : buffers_) sum += size_t(buffer.size());
  return sum;
}

}  // namespace ewa

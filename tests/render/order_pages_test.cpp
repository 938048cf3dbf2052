// OrderPages: the CPU partition's order list in GPU pages: layout, contents, sizes and reuse.
#include "render/order_pages.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "render_fixture.h"

namespace ewa {
namespace {

using test::RenderFixture;

class OrderPagesTest : public RenderFixture {};

// Each page's first position and length, in list order.
std::vector<std::pair<size_t, size_t>> layoutOf(const OrderPages& pages, size_t total) {
  std::vector<std::pair<size_t, size_t>> out;
  for (size_t e = 0; e < total;) {
    const OrderPages::Span s = pages.span(e);
    out.emplace_back(s.first, s.count);
    e = s.first + s.count;
  }
  return out;
}

// The list read back from the pages, position by position.
std::vector<uint32_t> readBack(const OrderPages& pages, size_t total) {
  std::vector<uint32_t> out(total);
  for (size_t e = 0; e < total; ++e) {
    const OrderPages::Span s = pages.span(e);
    s.buffer->getSubData(GLintptr((e - s.first) * 4), 4, &out[e]);
  }
  return out;
}

using Layout = std::vector<std::pair<size_t, size_t>>;

TEST_F(OrderPagesTest, PagesEndWhereSlabsDoAndCutOnlySlabsLongerThanAPage) {
  OrderPages pages(100);
  // Slabs of 30, 120 (longer than a page), 1, 99 and 40 entries.
  pages.layout({0, 30, 150, 151, 250}, 290);
  ASSERT_EQ(pages.pages(), 5u);
  pages.uploadAll(std::vector<uint32_t>(290).data());
  EXPECT_EQ(layoutOf(pages, 290), (Layout{{0, 30}, {30, 100}, {130, 21}, {151, 99}, {250, 40}}));
  // Small slabs share a page up to its size.
  pages.layout({0, 10, 20, 60, 95, 130}, 140);
  pages.uploadAll(std::vector<uint32_t>(140).data());
  EXPECT_EQ(layoutOf(pages, 140), (Layout{{0, 95}, {95, 45}}));
  // No breaks: pages of the page size and the rest.
  pages.layout({}, 250);
  pages.uploadAll(std::vector<uint32_t>(250).data());
  EXPECT_EQ(layoutOf(pages, 250), (Layout{{0, 100}, {100, 100}, {200, 50}}));
  pages.layout({0}, 0);
  EXPECT_EQ(pages.pages(), 0u);
}

TEST_F(OrderPagesTest, PagesHoldTheListAndAreSizedToItThenReused) {
  OrderPages pages(100);
  std::vector<uint32_t> list(250);
  std::iota(list.begin(), list.end(), 1000u);
  pages.layout({0, 100, 200}, list.size());
  for (size_t i = 0; i < pages.pages(); ++i) pages.uploadPage(i, list.data());
  EXPECT_EQ(readBack(pages, list.size()), list);
  EXPECT_EQ(pages.bufferCount(), 3u);
  EXPECT_EQ(pages.bytes(), 1000u);  // made exact: 100 + 100 + 50 entries

  // A longer list: the third page made again with an eighth to spare (up to a page), a new one.
  std::vector<uint32_t> longer(345);
  std::iota(longer.begin(), longer.end(), 7u);
  pages.layout({0, 100, 200, 280}, longer.size());
  pages.uploadAll(longer.data());
  EXPECT_EQ(readBack(pages, longer.size()), longer);
  EXPECT_EQ(layoutOf(pages, longer.size()), (Layout{{0, 100}, {100, 100}, {200, 80}, {280, 65}}));
  EXPECT_EQ(pages.bytes(), size_t(100 + 100 + (80 + 10) + 65) * 4);

  // A shorter list reuses the buffers as they are.
  const size_t bytes = pages.bytes();
  pages.layout({0, 60}, 120);
  pages.uploadAll(list.data());
  EXPECT_EQ(pages.bytes(), bytes);
  EXPECT_EQ(readBack(pages, 120), std::vector<uint32_t>(list.begin(), list.begin() + 120));

  // Another page size starts afresh.
  pages.setPageEntries(64);
  EXPECT_EQ(pages.bufferCount(), 0u);
  EXPECT_EQ(pages.bytes(), 0u);
}

}  // namespace
}  // namespace ewa

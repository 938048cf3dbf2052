// OrderPages: the CPU partition's order list in GPU pages: contents, page sizes and reuse.
#include "render/order_pages.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "render_fixture.h"

namespace ewa {
namespace {

using test::RenderFixture;

class OrderPagesTest : public RenderFixture {};

// The entries of the list's positions [first, first + count), read back from the pages.
std::vector<uint32_t> readBack(const OrderPages& pages, size_t first, size_t count) {
  std::vector<uint32_t> out(count);
  for (size_t i = 0; i < count; ++i)
    pages.page(first + i).getSubData(GLintptr(((first + i) % pages.pageEntries()) * 4), 4, &out[i]);
  return out;
}

TEST_F(OrderPagesTest, PiecesLandInTheirPagesAndPagesAreSizedToTheList) {
  OrderPages pages(100);
  std::vector<uint32_t> list(250);
  std::iota(list.begin(), list.end(), 1000u);
  // Uploaded in uneven pieces that straddle page boundaries, as a budgeted frame might.
  size_t done = 0;
  for (size_t piece : {30u, 120u, 1u, 99u}) {
    pages.upload(list.data() + done, done, piece, list.size());
    done += piece;
  }
  ASSERT_EQ(done, list.size());
  EXPECT_EQ(pages.pageCount(), 3u);
  EXPECT_EQ(readBack(pages, 0, list.size()), list);
  // Full pages and an exact tail: 100 + 100 + 50 entries.
  EXPECT_EQ(pages.page(0).size(), 400);
  EXPECT_EQ(pages.page(249).size(), 200);
  EXPECT_EQ(pages.bytes(), 1000u);

  // A longer list enlarges the tail page with an eighth to spare (up to a page) and adds one.
  std::vector<uint32_t> longer(330);
  std::iota(longer.begin(), longer.end(), 7u);
  pages.upload(longer.data(), 0, longer.size(), longer.size());
  EXPECT_EQ(pages.pageCount(), 4u);
  EXPECT_EQ(pages.page(200).size(), 400);  // needed 100: a whole page, no more
  EXPECT_EQ(pages.page(329).size(), 120);  // new: exactly the 30 entries needed
  EXPECT_EQ(readBack(pages, 0, longer.size()), longer);

  // A shorter list reuses the pages as they are.
  const size_t bytes = pages.bytes();
  pages.upload(list.data(), 0, 120, 120);
  EXPECT_EQ(pages.bytes(), bytes);
  EXPECT_EQ(readBack(pages, 0, 120), std::vector<uint32_t>(list.begin(), list.begin() + 120));

  // Another page size starts afresh.
  pages.setPageEntries(64);
  EXPECT_EQ(pages.pageCount(), 0u);
  EXPECT_EQ(pages.bytes(), 0u);
}

TEST_F(OrderPagesTest, TailPageGrowsByAnEighth) {
  OrderPages pages(1000);
  std::vector<uint32_t> list(1000 + 401, 5u);
  pages.upload(list.data(), 0, 1000 + 400, 1000 + 400);
  EXPECT_EQ(pages.page(1000).size(), 400 * 4);
  pages.upload(list.data(), 0, 1000 + 401, 1000 + 401);
  EXPECT_EQ(pages.page(1000).size(), (401 + 401 / 8) * 4);
}

}  // namespace
}  // namespace ewa

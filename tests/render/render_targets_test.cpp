// RenderTargets: a new size's images made a few at a time within a budget, and the last
// finished picture kept on show until a frame finishes in new images.
#include "render/render_targets.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "render_fixture.h"

namespace ewa::test {
namespace {

class RenderTargetsTest : public RenderFixture {};

constexpr double kTinyBudgetMs = 1e-6;
constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// Every image post-classification with pre-integration in quarters asks for, with normal sums
// and coarse slabs: nine.
TargetLayout fullLayout(int w, int h) {
  return TargetLayout{w, h, true, true, true, true, true};
}

// The pixel at (0, 0) of an RGBA8 texture.
std::vector<unsigned char> firstPixel(const gl::Texture& t, int w, int h) {
  std::vector<unsigned char> rgba(size_t(w) * h * 4);
  t.getImage(0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  return {rgba.begin(), rgba.begin() + 4};
}

TEST_F(RenderTargetsTest, ATinyBudgetMakesOneImageACallUntilAllAreThere) {
  RenderTargets t;
  const TargetLayout layout = fullLayout(40, 30);
  EXPECT_FALSE(t.ready(layout));
  int calls = 0;
  while (!t.prepare(layout, kTinyBudgetMs)) {
    ++calls;
    EXPECT_EQ(t.imagesMade(), 1) << "call " << calls;
    EXPECT_FALSE(t.ready(layout));
    ASSERT_LT(calls, 100);
  }
  EXPECT_EQ(t.imagesMade(), 1);  // the last image, then the framebuffers
  EXPECT_EQ(calls + 1, 9);
  EXPECT_TRUE(t.ready(layout));
  EXPECT_TRUE(t.pairedSlabs() && t.quarters() && t.normalSums() && t.coarseSlabs());
  EXPECT_TRUE(t.halfSlabs());
  EXPECT_EQ(t.width, 40);
  EXPECT_EQ(t.height, 30);
  // Made: nothing more to do, at any budget.
  EXPECT_TRUE(t.prepare(layout, kTinyBudgetMs));
  EXPECT_EQ(t.imagesMade(), 0);
  // Fewer images at the same size: only the framebuffers are made again.
  const TargetLayout fewer{40, 30, true, false, false, true, false};
  EXPECT_TRUE(t.prepare(fewer, kTinyBudgetMs));
  EXPECT_EQ(t.imagesMade(), 0);
  EXPECT_TRUE(t.pairedSlabs());
  EXPECT_FALSE(t.quarters() || t.normalSums() || t.coarseSlabs());
  EXPECT_EQ(t.bytes(), size_t(40 * 30) * (8 + 16 + 4 + 4 + 8));
  // A budget that never runs out makes a new size's images in one call.
  EXPECT_TRUE(t.prepare(fullLayout(50, 20), kNoLimit));
  EXPECT_EQ(t.imagesMade(), 9);
}

TEST_F(RenderTargetsTest, TheLastFinishedPictureStaysShownUntilTheNewSizeHasOne) {
  RenderTargets t;
  t.resize(16, 8);
  EXPECT_FALSE(t.shownOutput()) << "nothing finished yet";
  // A "picture": the output image cleared to a colour, as a final pass would draw it.
  const GLfloat red[4] = {1, 0, 0, 1};
  t.outputFbo.clearColor(0, red);
  t.outputFinished();
  ASSERT_TRUE(t.shownOutput());
  EXPECT_EQ(t.shownOutput().id(), t.output.id());
  const unsigned shown = t.shownOutput().id();

  // A new size, made over several calls: the 16x8 picture is shown throughout.
  const TargetLayout bigger{32, 24, true, false, false, false, false};
  int calls = 0;
  while (!t.prepare(bigger, kTinyBudgetMs)) {
    ++calls;
    EXPECT_EQ(t.shownOutput().id(), shown);
    EXPECT_EQ(t.shownWidth(), 16);
    EXPECT_EQ(t.shownHeight(), 8);
  }
  EXPECT_GE(calls, 4);
  EXPECT_EQ(t.shownOutput().id(), shown);
  EXPECT_EQ(firstPixel(t.shownOutput(), 16, 8), (std::vector<unsigned char>{255, 0, 0, 255}));
  EXPECT_EQ(t.bytes(), size_t(32 * 24) * (16 + 16 + 4 + 4 + 16) + size_t(16 * 8) * 4);

  // Abandoned before it finished, then another size: still the 16x8 picture.
  EXPECT_TRUE(t.prepare(TargetLayout{20, 20}, kNoLimit));
  EXPECT_EQ(t.shownOutput().id(), shown);
  EXPECT_EQ(t.shownWidth(), 16);

  // A frame finishes in the new images: they are shown, the old picture is freed.
  const GLfloat green[4] = {0, 1, 0, 1};
  t.outputFbo.clearColor(0, green);
  t.outputFinished();
  EXPECT_EQ(t.shownOutput().id(), t.output.id());
  EXPECT_EQ(t.shownWidth(), 20);
  EXPECT_EQ(t.shownHeight(), 20);
  EXPECT_EQ(firstPixel(t.shownOutput(), 20, 20), (std::vector<unsigned char>{0, 255, 0, 255}));
  EXPECT_EQ(t.bytes(), size_t(20 * 20) * (16 + 16 + 4 + 4));
}

// A final pass in bands over several steps: the picture shown stays until the pass is done,
// then the new one is, and the old image is used again for the next such pass.
TEST_F(RenderTargetsTest, ABandedFinalPassDrawsIntoAnImageNotShownUntilItIsDone) {
  RenderTargets t;
  t.resize(16, 8);
  const GLfloat red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
  t.outputFbo.clearColor(0, red);
  t.outputFinished();
  const unsigned first = t.output.id();
  const size_t bytes = t.bytes();

  t.beginOutput();
  EXPECT_NE(t.output.id(), first);
  EXPECT_EQ(t.shownOutput().id(), first);
  t.outputFbo.clearColor(0, green);  // a band, drawn through the framebuffer
  EXPECT_EQ(firstPixel(t.shownOutput(), 16, 8), (std::vector<unsigned char>{255, 0, 0, 255}));
  EXPECT_EQ(t.bytes(), bytes + 16 * 8 * 4);  // both pictures
  t.outputFinished();
  const unsigned second = t.output.id();
  EXPECT_EQ(t.shownOutput().id(), second);
  EXPECT_EQ(firstPixel(t.shownOutput(), 16, 8), (std::vector<unsigned char>{0, 255, 0, 255}));
  EXPECT_EQ(t.bytes(), bytes + 16 * 8 * 4);  // the first kept as the spare

  // The next banded pass draws into the first image again: nothing new is allocated.
  t.beginOutput();
  EXPECT_EQ(t.output.id(), first);
  EXPECT_EQ(t.shownOutput().id(), second);
  t.outputFbo.clearColor(0, blue);
  EXPECT_EQ(firstPixel(t.shownOutput(), 16, 8), (std::vector<unsigned char>{0, 255, 0, 255}));
  t.outputFinished();
  EXPECT_EQ(firstPixel(t.shownOutput(), 16, 8), (std::vector<unsigned char>{0, 0, 255, 255}));

  // Not shown (a new size's output, before its first frame is done): drawn into as it is.
  t.resize(24, 8);
  const unsigned fresh = t.output.id();
  t.beginOutput();
  EXPECT_EQ(t.output.id(), fresh);
  EXPECT_EQ(t.shownWidth(), 16);
}

}  // namespace
}  // namespace ewa::test

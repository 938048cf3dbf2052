// KeyTrickle: a key tapped between two NewFrames is seen down by one of them and up by the
// next, in order, and nothing is held that did not need to be.
#include "ui/key_trickle.h"

#include <gtest/gtest.h>

#include <vector>

namespace ewa {
namespace {

constexpr int kRelease = 0, kPress = 1, kRepeat = 2;
constexpr int kCtrl = 341, kA = 65, kEnter = 257;
using Pairs = std::vector<std::pair<int, int>>;

KeyEvent event(int key, int action) {
  KeyEvent e;
  e.key = key;
  e.action = action;
  e.change = action == kPress     ? KeyChange::Press
             : action == kRelease ? KeyChange::Release
                                  : KeyChange::Repeat;
  return e;
}

// One UI frame: the held events delivered before its NewFrame (key, action), then the NewFrame.
Pairs frame(KeyTrickle& t) {
  Pairs out;
  for (const KeyEvent& e : t.beforeNewFrame()) out.emplace_back(e.key, e.action);
  t.afterNewFrame();
  return out;
}

TEST(KeyTrickle, ATapBetweenTwoFramesIsReleasedAfterOneSawItDown) {
  KeyTrickle t;
  frame(t);
  EXPECT_TRUE(t.arrive(event(kEnter, kPress)));
  EXPECT_FALSE(t.arrive(event(kEnter, kRelease)));   // the next NewFrame must see Enter down
  EXPECT_EQ(frame(t), Pairs{});                      // it does
  EXPECT_EQ(frame(t), (Pairs{{kEnter, kRelease}}));  // and the one after sees it up
  EXPECT_EQ(t.heldCount(), 0u);
}

TEST(KeyTrickle, EventsOfKeysThatDidNotChangeSinceTheLastFramePassAtOnce) {
  KeyTrickle t;
  EXPECT_TRUE(t.arrive(event(kA, kPress)));
  frame(t);
  EXPECT_TRUE(t.arrive(event(kA, kRepeat)));   // a repeat changes nothing
  EXPECT_TRUE(t.arrive(event(kA, kRelease)));  // its press was seen
  EXPECT_TRUE(t.arrive(event(kEnter, kPress)));
  EXPECT_EQ(t.heldCount(), 0u);
}

// Ctrl+A tapped between two frames: Ctrl and A are down together in the next frame, and both
// are released before the one after, in the order they came (Ctrl's release waits behind A's).
TEST(KeyTrickle, AChordKeepsItsOrder) {
  KeyTrickle t;
  EXPECT_TRUE(t.arrive(event(kCtrl, kPress)));
  EXPECT_TRUE(t.arrive(event(kA, kPress)));
  EXPECT_FALSE(t.arrive(event(kA, kRelease)));
  EXPECT_FALSE(t.arrive(event(kCtrl, kRelease)));
  EXPECT_EQ(frame(t), Pairs{});
  EXPECT_EQ(frame(t), (Pairs{{kA, kRelease}, {kCtrl, kRelease}}));
}

// xdotool's Ctrl+A when a NewFrame falls between Ctrl's press and A's: Ctrl's release (sent
// before A's) waits until a frame has seen A down, with Ctrl.
TEST(KeyTrickle, AModifierIsHeldDownUntilTheKeyPressedWithItIsSeen) {
  KeyTrickle t;
  EXPECT_TRUE(t.arrive(event(kCtrl, kPress)));
  EXPECT_EQ(frame(t), Pairs{});  // sees Ctrl down
  EXPECT_TRUE(t.arrive(event(kA, kPress)));
  EXPECT_FALSE(t.arrive(event(kCtrl, kRelease)));
  EXPECT_FALSE(t.arrive(event(kA, kRelease)));
  EXPECT_EQ(frame(t), Pairs{});  // sees Ctrl and A down
  EXPECT_EQ(frame(t), (Pairs{{kCtrl, kRelease}, {kA, kRelease}}));
}

// A key tapped twice between two frames is seen down, up, down, up by four frames: two
// presses, not one; Enter, pressed after them, waits its turn.
TEST(KeyTrickle, TwoTapsOfOneKeyAreTwoPresses) {
  KeyTrickle t;
  EXPECT_TRUE(t.arrive(event(kA, kPress)));
  EXPECT_FALSE(t.arrive(event(kA, kRelease)));
  EXPECT_FALSE(t.arrive(event(kA, kPress)));
  EXPECT_FALSE(t.arrive(event(kA, kRelease)));
  EXPECT_FALSE(t.arrive(event(kEnter, kPress)));
  EXPECT_EQ(frame(t), Pairs{});
  EXPECT_EQ(frame(t), (Pairs{{kA, kRelease}}));
  EXPECT_EQ(frame(t), (Pairs{{kA, kPress}}));
  EXPECT_EQ(frame(t), (Pairs{{kA, kRelease}, {kEnter, kPress}}));
  EXPECT_EQ(t.heldCount(), 0u);
}

}  // namespace
}  // namespace ewa

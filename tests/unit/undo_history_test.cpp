// UndoHistory: steps from settled snapshots, undo and redo in order, redo dropped by an edit.
#include "core/undo_history.h"

#include <gtest/gtest.h>

#include "core/transfer_function.h"

namespace ewa {
namespace {

TEST(UndoHistory, UndoesAndRedoesSettledStepsInOrder) {
  UndoHistory<int> h(0);
  EXPECT_FALSE(h.canUndo(0));
  EXPECT_FALSE(h.undo(0));
  EXPECT_FALSE(h.settle(0));  // nothing changed: no step
  EXPECT_TRUE(h.settle(1));
  EXPECT_FALSE(h.settle(1));
  EXPECT_TRUE(h.settle(2));
  EXPECT_EQ(h.undoSteps(), 2u);
  EXPECT_EQ(h.undo(2), 1);
  EXPECT_EQ(h.undo(1), 0);
  EXPECT_FALSE(h.undo(0));
  EXPECT_TRUE(h.canRedo(0));
  EXPECT_EQ(h.redo(0), 1);
  EXPECT_EQ(h.redo(1), 2);
  EXPECT_FALSE(h.redo(2));
}

TEST(UndoHistory, AnEditNotYetSettledIsOneStepAndDropsTheRedoSteps) {
  UndoHistory<int> h(0);
  h.settle(5);
  // A drag still under way (7, never settled) is undone back to the last settled value.
  EXPECT_TRUE(h.canUndo(7));
  EXPECT_EQ(h.undo(7), 5);
  EXPECT_EQ(h.redo(5), 7);
  EXPECT_EQ(h.undo(7), 5);
  // An edit after an undo: the redo steps go, as in any editor.
  EXPECT_FALSE(h.canRedo(6));
  EXPECT_FALSE(h.redo(6));
  EXPECT_EQ(h.redoSteps(), 0u);
  EXPECT_EQ(h.undo(6), 5);
  EXPECT_EQ(h.undo(5), 0);
}

TEST(UndoHistory, KeepsAtMostItsLimitDroppingTheOldest) {
  UndoHistory<int> h(0, 3);
  for (int v = 1; v <= 5; ++v) h.settle(v);
  EXPECT_EQ(h.undoSteps(), 3u);
  EXPECT_EQ(h.undo(5), 4);
  EXPECT_EQ(h.undo(4), 3);
  EXPECT_EQ(h.undo(3), 2);
  EXPECT_FALSE(h.undo(2));  // 1 and 0 were the oldest
}

TEST(UndoHistory, TransferFunctionsAreStepsByValue) {
  TransferFunction a;
  a.addOpacityPoint(0.0, 0.0);
  a.addOpacityPoint(100.0, 1.0);
  UndoHistory<TransferFunction> h(a);
  TransferFunction b = a;
  b.moveOpacityPoint(1, 80.0, 0.5);
  TransferFunction c = b;
  c.addColorPoint(40.0, {1.0, 0.0, 0.0});
  EXPECT_TRUE(h.settle(b));
  EXPECT_TRUE(h.settle(c));
  EXPECT_EQ(*h.undo(c), b);
  EXPECT_EQ(*h.undo(b), a);
  EXPECT_EQ(*h.redo(a), b);
}

}  // namespace
}  // namespace ewa

// The key table: every command a key gives has a row, each row is reachable, and the modifiers
// pick the rows they did before the table (Ctrl+Shift+C copies the view, Shift+C pages back).
#include "ui/key_bindings.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <set>

namespace ewa {
namespace {

KeyCommand commandFor(int key, int mods) {
  const KeyBinding* b = keyBindingFor(key, mods);
  EXPECT_NE(b, nullptr) << key << " " << mods;
  return b ? b->command : KeyCommand::Quit;
}

// The handler (WindowInput::onKey) acts only on what keyBindingFor finds, so every key it
// handles has a row; here every command but the double-click's has a key.
TEST(KeyBindings, EveryCommandHasAKey) {
  std::set<int> bound;
  for (const KeyBinding& b : keyBindings()) bound.insert(int(b.command));
  for (int c = 0; c <= int(KeyCommand::Quit); ++c) {
    if (KeyCommand(c) != KeyCommand::CentreOnCursor) {
      EXPECT_TRUE(bound.count(c)) << "command " << c;
    }
  }
}

TEST(KeyBindings, EveryRowIsReachable) {
  for (const KeyBinding& b : keyBindings()) {
    EXPECT_EQ(keyBindingFor(b.key, b.mods), &b) << keyText(b);
    EXPECT_NE(std::string(b.does), "");
  }
}

TEST(KeyBindings, ModifiersPickTheRow) {
  EXPECT_EQ(commandFor(GLFW_KEY_C, 0), KeyCommand::NextChannel);
  EXPECT_EQ(commandFor(GLFW_KEY_C, GLFW_MOD_SHIFT), KeyCommand::PreviousChannel);
  EXPECT_EQ(commandFor(GLFW_KEY_C, GLFW_MOD_CONTROL), KeyCommand::CopyView);
  EXPECT_EQ(commandFor(GLFW_KEY_C, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), KeyCommand::CopyView);
  EXPECT_EQ(commandFor(GLFW_KEY_Z, GLFW_MOD_CONTROL), KeyCommand::Undo);
  EXPECT_EQ(commandFor(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), KeyCommand::Redo);
  EXPECT_EQ(commandFor(GLFW_KEY_Y, GLFW_MOD_CONTROL), KeyCommand::Redo);
  EXPECT_EQ(commandFor(GLFW_KEY_S, GLFW_MOD_CONTROL), KeyCommand::SaveVolume);
  EXPECT_EQ(commandFor(GLFW_KEY_R, GLFW_MOD_CONTROL), KeyCommand::ResetCamera);  // others ignored
  EXPECT_EQ(commandFor(GLFW_KEY_3, GLFW_MOD_ALT), KeyCommand::ViewPlusY);
  EXPECT_EQ(commandFor(GLFW_KEY_ESCAPE, 0), KeyCommand::Quit);
  EXPECT_EQ(keyBindingFor(GLFW_KEY_O, 0), nullptr);  // Ctrl+O only
  EXPECT_EQ(keyBindingFor(GLFW_KEY_Z, GLFW_MOD_SHIFT), nullptr);
}

TEST(KeyBindings, KeyText) {
  EXPECT_EQ(keyText(*keyBindingFor(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT)), "Ctrl+Shift+Z");
  EXPECT_EQ(keyText(*keyBindingFor(GLFW_KEY_PAGE_DOWN, 0)), "Page Down");
  EXPECT_EQ(keyText(*keyBindingFor(GLFW_KEY_F1, 0)), "F1");
  EXPECT_EQ(keyText(*keyBindingFor(GLFW_KEY_6, 0)), "6");
}

}  // namespace
}  // namespace ewa

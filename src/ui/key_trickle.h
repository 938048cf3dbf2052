// KeyTrickle: key events held back so that each ImGui frame sees every press (no GLFW, no
// ImGui: unit tested).
#pragma once

#include <algorithm>
#include <deque>
#include <vector>

namespace ewa {

enum class KeyChange { Press, Release, Repeat };

// One key callback's arguments (GLFW's), with what the action does to the key.
struct KeyEvent {
  int key = 0, scancode = 0, action = 0, mods = 0;
  KeyChange change = KeyChange::Press;
};

// Dear ImGui 1.86 samples which keys are down once a frame, in NewFrame (its input queue came
// in 1.87): a key pressed and released between two NewFrames (a quick tap while a slow frame
// is drawn, or xdotool's 12 ms) was never seen down, so Enter, Backspace or Ctrl+A in a text
// field were lost. This holds an event back, and every event after it so that order is kept,
// when its key already changed since the last NewFrame, or when it is a release and some key
// was pressed since then (xdotool releases Ctrl before A: the frame must see them down
// together). Before each NewFrame it lets through what it may.
class KeyTrickle {
 public:
  // An event as it arrives: true when it is to be delivered now, false when it is held.
  bool arrive(const KeyEvent& e) {
    if (!held_.empty() || !mayPass(e)) {
      held_.push_back(e);
      return false;
    }
    passed(e);
    return true;
  }

  // Just before a NewFrame: the held events to deliver now, oldest first, up to the first that
  // must wait for this NewFrame to sample what came before it.
  std::vector<KeyEvent> beforeNewFrame() {
    std::vector<KeyEvent> out;
    while (!held_.empty() && mayPass(held_.front())) {
      passed(held_.front());
      out.push_back(held_.front());
      held_.pop_front();
    }
    return out;
  }

  // Just after a NewFrame: every change so far has been sampled.
  void afterNewFrame() {
    changed_.clear();
    pressed_ = false;
  }

  size_t heldCount() const { return held_.size(); }

 private:
  bool mayPass(const KeyEvent& e) const {
    if (e.change == KeyChange::Repeat) return true;  // the key stays down
    if (e.change == KeyChange::Release && pressed_) return false;
    return std::find(changed_.begin(), changed_.end(), e.key) == changed_.end();
  }
  void passed(const KeyEvent& e) {
    if (e.change == KeyChange::Repeat) return;
    changed_.push_back(e.key);
    pressed_ = pressed_ || e.change == KeyChange::Press;
  }

  std::deque<KeyEvent> held_;
  std::vector<int> changed_;  // keys pressed or released since the last NewFrame
  bool pressed_ = false;      // a key pressed since the last NewFrame
};

}  // namespace ewa

// UndoHistory: undo and redo over settled snapshots of a value edited in steps (the transfer
// function in the editor), so a drag of many frames is one step and any kind of edit counts.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

namespace ewa {

template <class T>
class UndoHistory {
 public:
  explicit UndoHistory(T start, size_t limit = 100) : settled_(std::move(start)), limit_(limit) {}

  // Called whenever an edit may have ended (no drag, no widget held): when `current` differs
  // from the last settled value, that value becomes an undo step and the redo steps are
  // dropped. Returns whether a step was added.
  bool settle(const T& current) {
    if (current == settled_) return false;
    undo_.push_back(std::move(settled_));
    if (undo_.size() > limit_) undo_.pop_front();  // the oldest steps go first
    settled_ = current;
    redo_.clear();
    return true;
  }

  bool canUndo(const T& current) const { return !undo_.empty() || !(current == settled_); }
  bool canRedo(const T& current) const { return !redo_.empty() && current == settled_; }
  size_t undoSteps() const { return undo_.size(); }
  size_t redoSteps() const { return redo_.size(); }

  // The value before the last step (an edit not yet settled counts as one), `current` kept
  // to redo; nothing when there is nothing to undo.
  std::optional<T> undo(const T& current) { return step(undo_, redo_, current); }
  // The value the last undo left, `current` kept to undo; nothing when there is none or
  // `current` was edited since (an edit after an undo drops the redo steps, as editors do).
  std::optional<T> redo(const T& current) { return step(redo_, undo_, current); }

 private:
  std::optional<T> step(std::deque<T>& from, std::deque<T>& to, const T& current) {
    settle(current);  // may drop the redo steps
    if (from.empty()) return std::nullopt;
    to.push_back(std::move(settled_));
    settled_ = std::move(from.back());
    from.pop_back();
    return settled_;
  }

  std::deque<T> undo_, redo_;
  T settled_;
  size_t limit_;
};

}  // namespace ewa

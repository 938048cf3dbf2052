// BackgroundArena: oneTBB work that yields to a window's threads, its threads at the background
// priority (thread_priority.h) while they work in it.
#pragma once

#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <utility>

namespace ewa {

// A window's CPU frames run here on a machine with as few cores as llvmpipe's threads and the
// UI want: the UI frames keep their time, the frame takes what is left. A thread lowered once
// stays lowered (raising a priority needs rights): in a window process all such work is
// background work.
class BackgroundArena {
 public:
  BackgroundArena() : observer_(arena_) {}
  BackgroundArena(const BackgroundArena&) = delete;
  BackgroundArena& operator=(const BackgroundArena&) = delete;

  // Runs `f` in the arena (its parallel loops on the arena's threads); returns what it returns.
  template <typename F>
  auto execute(F&& f) {
    return arena_.execute(std::forward<F>(f));
  }

 private:
  class Observer : public tbb::task_scheduler_observer {
   public:
    explicit Observer(tbb::task_arena& arena);
    ~Observer() override;
    void on_scheduler_entry(bool worker) override;
  };
  tbb::task_arena arena_;
  Observer observer_;
};

}  // namespace ewa

// BackgroundArena's observer: each thread entering the arena lowers its own priority.
#include "core/background_arena.h"

#include "core/thread_priority.h"

namespace ewa {

BackgroundArena::Observer::Observer(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
  observe(true);
}

BackgroundArena::Observer::~Observer() {
  observe(false);  // before the arena goes: no entry may run on a half-destroyed observer
}

void BackgroundArena::Observer::on_scheduler_entry(bool) {
  lowerThisThreadPriority();
}

}  // namespace ewa

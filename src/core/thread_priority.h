// Background threads yield to the window's: a lower scheduling priority for the calling thread.
#pragma once

namespace ewa {

// The nice value background work runs at (Linux: 0 is the default, 19 the lowest priority).
// CFS then gives a nice-10 thread about a tenth of a core's time against a nice-0 one.
constexpr int kBackgroundNice = 10;

// Lowers the calling thread's priority to kBackgroundNice (threads it starts afterwards
// inherit it). For work a window waits for only when it has nothing else to do (a new splat
// set being classified while the frames draw the old one), on a machine with as few cores as
// llvmpipe's threads and the window's together want. Best effort: where the system refuses,
// or has no per-thread priorities, nothing changes.
void lowerThisThreadPriority();

}  // namespace ewa

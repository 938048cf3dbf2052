// Process-wide heap setting for software OpenGL, made once at start-up by main().
#pragma once

namespace ewa {

// llvmpipe allocates and frees its per-draw storage (vertex outputs, binned primitives: tens of
// MB for a frame of splats) draw after draw; glibc hands the top of the heap back to the kernel
// after each free and the next draw faults every page in again. Keeping up to 1 GiB of freed
// heap for reuse took a one-shot 512x512 picture of engine from 5.1 s to 3.0 s (same image,
// same peak memory; README, "One-shot pictures"). Leaves glibc's setting alone where the user
// chose one (GLIBC_TUNABLES naming trim_threshold, or MALLOC_TRIM_THRESHOLD_). Returns whether
// it changed it.
bool keepFreedHeapForReuse();

}  // namespace ewa

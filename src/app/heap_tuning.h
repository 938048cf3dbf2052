// Process-wide heap settings for software OpenGL, made once at start-up by main().
#pragma once

#include <string>

namespace ewa {

// llvmpipe allocates and frees its per-draw storage (vertex outputs, binned primitives: tens of
// MB for a frame of splats) draw after draw; glibc hands the top of the heap back to the kernel
// after each free and the next draw faults every page in again. Keeping up to 1 GiB of freed
// heap for reuse took a one-shot 512x512 picture of engine from 5.1 s to 3.0 s (same image,
// same peak memory; docs/dev/performance.md, "One-shot pictures and files"). Leaves glibc's setting
// alone where the user chose one (GLIBC_TUNABLES naming trim_threshold, or MALLOC_TRIM_THRESHOLD_).
// Returns whether it changed it.
bool keepFreedHeapForReuse();

// Where transparent huge pages are given only to memory that asks (the kernel's "madvise"
// mode, Debian's default), runs this program again at once (same process, execv of
// /proc/self/exe with `argv`) with glibc's tunable glibc.malloc.hugetlb=1, so that malloc asks
// for them. llvmpipe zero-fills every buffer it makes, and on this project's machine a 4 KiB
// page fault costs so much that a 512^3 volume's 0.58 GB splat list took 2.7 s to upload (one
// frozen window frame); with huge pages 0.8 s, and its headless picture 47 s instead of 63 s
// (docs/dev/performance.md, "Huge pages and the launcher"). Leaves things as they are
// where GLIBC_TUNABLES already names malloc.hugetlb (the user's choice: glibc.malloc.hugetlb=0
// turns it off), off Linux and glibc, or when the kernel's mode is "always" or "never". Returns
// only if it did not run again. Started by its launcher (launcher_main.cpp), the viewer finds
// the tunable set already and runs once.
void askForHugePages(char** argv);
// The GLIBC_TUNABLES value (`tunables`: the variable's, or null) with glibc.malloc.hugetlb=1
// added, where askForHugePages would run the program again with it; empty where it would not.
std::string hugePageTunables(const char* tunables);
// Whether this process's large allocations get transparent huge pages: glibc asks for them
// (GLIBC_TUNABLES has glibc.malloc.hugetlb=1) or the kernel gives them unasked ("always").
bool hugePagesInUse();

}  // namespace ewa

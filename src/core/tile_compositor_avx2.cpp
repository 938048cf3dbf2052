// The CPU splatter's tile composite compiled for AVX2 and FMA (CMakeLists.txt gives this file
// -mavx2 -mfma on x86-64; tile_compositor.cpp calls it where the machine has them). flatten
// inlines what it calls, and the shared formulas GCC would leave out of line as cold are always
// inlined, so this file defines no function but its own (tile_kernel_isa_symbols).
#if defined(__AVX2__) && defined(__FMA__)

#define EWA_TILE_ISA avx2
#include "core/tile_composite_kernel.h"
#include "core/tile_post_kernel.h"

namespace ewa::tile_kernel::avx2 {

void compositeTile(const TileWork& work, bool series, bool clipped);

__attribute__((flatten)) void compositeTile(const TileWork& work, bool series, bool clipped) {
  gatherTileFor(work, series, clipped);
}

}  // namespace ewa::tile_kernel::avx2

#endif

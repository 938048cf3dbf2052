// TileBins: the compute tile splatters' binning, each item listed in the buckets it reaches (a
// screen tile, or a tile and slab): per-bucket counts, their exclusive scan, the lists.
#pragma once

#include <cstddef>

#include "gl/buffer.h"
#include "gl/program.h"

namespace ewa {

class TileBins {
 public:
  // `what` names the buffers when the GL runs out of memory for them.
  explicit TileBins(const char* what) : what_(what) {}

  // Clears `buckets` counts, runs `count` over `items` invocations (groups of 256), `scan` once
  // (one group), reads the lists' length back, sizes the lists and runs `scatter` over the items
  // again. The counts (then the next free entry) are at storage binding 1, each bucket's first
  // entry (buckets + 1 of them) at 2, the lists at `listBinding`; they stay bound for the pass
  // that reads them. The programs' other buffers and uniforms are the caller's. Returns the
  // lists' length.
  size_t bin(const gl::Program& count, const gl::Program& scan, const gl::Program& scatter,
             size_t items, size_t buckets, GLuint listBinding);
  // Bytes of its buffers.
  size_t bytes() const { return size_t(cursor_.size() + offsets_.size() + lists_.size()); }

 private:
  const char* what_;
  gl::Buffer cursor_, offsets_, lists_;
};

}  // namespace ewa

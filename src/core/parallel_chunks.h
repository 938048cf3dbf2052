// Runs a loop's contiguous chunks on the machine's cores, in a fixed order of chunks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace ewa {

// Voxels (or splats) of work below which a chunk is not worth a thread of its own.
constexpr size_t kMinChunkWork = 65536;

// The least items a chunk should take when each item is `workPerItem` voxels of work (a
// slice, a row): at least 1, and kMinChunkWork voxels a chunk.
inline size_t minItemsPerChunk(size_t workPerItem) {
  return workPerItem == 0 ? 1
                          : std::max<size_t>(1, (kMinChunkWork + workPerItem - 1) / workPerItem);
}

// The threads parallelChunks uses for `requested`: 0 means the machine's cores (at most 16),
// anything else is taken as it is.
unsigned workerThreads(unsigned requested);

// Splits [0, count) into at most workerThreads(threads) contiguous chunks of at least
// `minPerChunk` items (one chunk, on the calling thread, if count is smaller) and calls
// fn(first, last, chunk) for each, chunk 0 on the calling thread. Chunk c covers the items
// after chunk c - 1's, so results kept per chunk and joined in chunk order come out in the
// sequential loop's order whatever the thread count. Returns the number of chunks. An exception
// from any chunk is rethrown (the first chunk's in order) after every chunk has finished.
size_t parallelChunks(size_t count, size_t minPerChunk, unsigned threads,
                      const std::function<void(size_t first, size_t last, size_t chunk)>& fn);

// The number of chunks parallelChunks would use for these arguments.
size_t chunkCount(size_t count, size_t minPerChunk, unsigned threads);

// parallelChunks for loops that keep state per chunk: fn(first, last) returns its chunk's
// result (a count, a range, its part of a list), and the results come back in chunk order, so
// joined in that order they are the sequential loop's. Each chunk's result is stored once, when
// it returns: chunks that add into shared slots instead slow each other (one cache line).
template <typename T, typename Fn>
std::vector<T> parallelChunkResults(size_t count, size_t minPerChunk, unsigned threads, Fn fn) {
  std::vector<T> results(chunkCount(count, minPerChunk, threads));
  parallelChunks(count, minPerChunk, threads, [&](size_t first, size_t last, size_t chunk) {
    results[chunk] = fn(first, last);
  });
  return results;
}

}  // namespace ewa

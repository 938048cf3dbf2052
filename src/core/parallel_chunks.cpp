// Runs a loop's contiguous chunks on the machine's cores, in a fixed order of chunks.
#include "core/parallel_chunks.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace ewa {

unsigned workerThreads(unsigned requested) {
  if (requested > 0) return requested;
  return std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
}

size_t chunkCount(size_t count, size_t minPerChunk, unsigned threads) {
  if (count == 0) return 0;
  const size_t most = count / std::max<size_t>(minPerChunk, 1);
  return std::clamp<size_t>(most, 1, workerThreads(threads));
}

size_t parallelChunks(size_t count, size_t minPerChunk, unsigned threads,
                      const std::function<void(size_t, size_t, size_t)>& fn) {
  const size_t chunks = chunkCount(count, minPerChunk, threads);
  if (chunks == 0) return 0;
  std::vector<std::exception_ptr> errors(chunks);
  auto run = [&](size_t c) {
    try {
      fn(count * c / chunks, count * (c + 1) / chunks, c);
    } catch (...) {
      errors[c] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(chunks - 1);
  for (size_t c = 1; c < chunks; ++c) pool.emplace_back(run, c);
  run(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return chunks;
}

}  // namespace ewa

// IceTCompositor: the ranks' premultiplied float pictures blended in visibility order by IceT
// over MPI; X-ray sums and MIP maxima by MPI reductions.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ewa::dist {

// IceT's multi-tile strategy and single-image strategy, by name: "reduce" (the default),
// "sequential", "direct", "split", "vtree"; "automatic" (the default), "bswap", "tree",
// "radixk", "radixkr", "bswap-folding". False for any other name.
bool parseIceTStrategy(const std::string& name, int* strategy);
bool parseIceTSingleImageStrategy(const std::string& name, int* strategy);

class IceTCompositor {
 public:
  // An IceT context on `comm` with this strategy (ICET_STRATEGY_*) and single-image strategy
  // (ICET_SINGLE_IMAGE_STRATEGY_*), compositing RGBA floats without depth in ordered BLEND mode.
  // Throws std::invalid_argument, with one line saying so, for a strategy that does not keep
  // the order (ICET_STRATEGY_SUPPORTS_ORDERING false: split and vtree, which return wrong
  // pictures from 3 ranks on). Collective: every rank of `comm` constructs one.
  explicit IceTCompositor(MPI_Comm comm, int strategy = 0, int singleImageStrategy = 0);
  ~IceTCompositor();
  IceTCompositor(const IceTCompositor&) = delete;
  IceTCompositor& operator=(const IceTCompositor&) = delete;

  // Blends every rank's picture: `rgba` is width x height premultiplied RGBA floats (any row
  // order, the same on every rank); `order` lists the ranks of `comm` front to back, the same
  // on every rank. Front to back, a pixel is front + (1 - front alpha) * back. Returns the
  // blended picture on rank `root` (0), empty on the others. Collective. Throws
  // std::runtime_error when IceT reports an error.
  std::vector<float> blend(const std::vector<float>& rgba, int width, int height,
                           const std::vector<int>& order);
  // The bytes this rank sent to other ranks in the last blend (IceT's ICET_BYTES_SENT, which
  // icetCompositeImage resets and counts): its share of the composite's traffic, compressed
  // (IceT sends only runs of non-transparent pixels). 0 before the first blend; a few bytes (IceT's
  // own messages) on one rank.
  std::int64_t lastBytesSent() const { return lastBytesSent_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
  void* communicator_ = nullptr;  // IceTCommunicator
  void* context_ = nullptr;       // IceTContext
  int tileWidth_ = 0, tileHeight_ = 0;
  std::int64_t lastBytesSent_ = 0;
};

// Element-wise sum (X-ray's optical depths) or maximum (MIP) of every rank's `values` on rank
// `root`; empty on the others. Collective; every rank passes as many values. `bytesSent`, when
// given, gets the bytes this rank hands to the reduction to leave it (reductionBytesSent).
std::vector<float> reduceSum(const std::vector<float>& values, MPI_Comm comm, int root = 0,
                             std::int64_t* bytesSent = nullptr);
std::vector<float> reduceMax(const std::vector<float>& values, MPI_Comm comm, int root = 0,
                             std::int64_t* bytesSent = nullptr);

// The bytes a rank hands over in reduceSum or reduceMax of `count` floats: all of them off the
// root, none on it. MPI's binomial-tree reduction sends each non-root rank's partial result once
// to its parent, so this is also what leaves the rank there; other MPI algorithms move about as
// much in total, spread differently.
std::int64_t reductionBytesSent(size_t count, int rank, int root);

}  // namespace ewa::dist

// AsyncSplatBuilder: classifies a volume into splats on a worker thread, newest request wins.
#pragma once

#include <cstddef>
#include <cstdint>
#include <future>
#include <optional>

#include "core/splat_attributes.h"
#include "core/splat_set.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

// While the user drags a transfer-function point, every frame asks for a new splat set. One
// build runs at a time; requests that arrive meanwhile collapse into the newest, which starts
// when the running one ends. The window keeps drawing the old set (with the new colours from
// the GPU table) and swaps the new one in when poll() hands it over.
// A finished build and the classification it was made under.
struct BuiltSplats {
  ClassifiedSplats splats;
  Classification classification;
};

class AsyncSplatBuilder {
 public:
  AsyncSplatBuilder() = default;
  ~AsyncSplatBuilder();  // waits for a running build (it only reads the volume)
  AsyncSplatBuilder(const AsyncSplatBuilder&) = delete;
  AsyncSplatBuilder& operator=(const AsyncSplatBuilder&) = delete;

  // Asks for the splats of `volume` under `tf` and `classification` (classifySplats, at most
  // `maxSplats`). The volume must outlive the build.
  void request(const Volume& volume, const TransferFunction& tf,
               const Classification& classification = {}, size_t maxSplats = SIZE_MAX);
  // A finished set when one is ready (during a long drag it may already be older than the
  // newest request, which then starts building). Never blocks; rethrows a build's exception.
  std::optional<BuiltSplats> poll();
  // True while a build runs or waits.
  bool busy() const { return running_.valid() || pending_.has_value(); }
  // Blocks until everything asked for is built and returns the newest set (for tests and exit).
  std::optional<BuiltSplats> finish();

 private:
  struct Request {
    const Volume* volume;
    TransferFunction tf;
    Classification classification;
    size_t maxSplats;
  };
  void start(Request request);

  std::future<BuiltSplats> running_;
  std::optional<Request> pending_;
};

}  // namespace ewa

// AsyncSplatBuilder: one std::async build at a time, later requests coalesced into the newest.
#include "core/async_splat_builder.h"

#include <chrono>

#include "core/thread_priority.h"

namespace ewa {

AsyncSplatBuilder::~AsyncSplatBuilder() {
  if (running_.valid()) running_.wait();
}

void AsyncSplatBuilder::start(Request request) {
  running_ = std::async(std::launch::async, [r = std::move(request)] {
    // The window draws the set before meanwhile: its frames (and llvmpipe's threads) come
    // first on a machine of few cores; the classification's own worker threads inherit this.
    lowerThisThreadPriority();
    return BuiltSplats{classifySplats(*r.volume, r.tf, r.classification, r.maxSplats),
                       r.classification};
  });
}

void AsyncSplatBuilder::request(const Volume& volume, const TransferFunction& tf,
                                const Classification& classification, size_t maxSplats) {
  Request r{&volume, tf, classification, maxSplats};
  if (running_.valid()) {
    pending_ = std::move(r);  // replaces an older waiting request: only the newest matters
  } else {
    start(std::move(r));
  }
}

std::optional<BuiltSplats> AsyncSplatBuilder::poll() {
  if (!running_.valid()) return std::nullopt;
  if (running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  BuiltSplats set = running_.get();  // rethrows a build failure to the caller
  if (pending_) {
    // Out of date already, but closer than what is drawn: hand it over and build the newest.
    Request next = std::move(*pending_);
    pending_.reset();
    start(std::move(next));
  }
  return set;
}

std::optional<BuiltSplats> AsyncSplatBuilder::finish() {
  std::optional<BuiltSplats> last;
  while (running_.valid()) {
    running_.wait();
    if (auto set = poll()) last = std::move(set);
  }
  return last;
}

}  // namespace ewa

// UploadContext: a GL context sharing another's objects, bound by one worker thread at a time
// to fill buffers while the main context draws.
#pragma once

namespace ewa::platform {

class UploadContext {
 public:
  UploadContext() = default;
  virtual ~UploadContext() = default;
  UploadContext(const UploadContext&) = delete;
  UploadContext& operator=(const UploadContext&) = delete;

  // Binds the context to the calling thread. GL calls there go through the function pointers
  // loaded for the context it shares with (one library: the same entry points). Throws
  // ContextError when it cannot be bound.
  virtual void bind() = 0;
  // Unbinds it from the calling thread: before another thread binds it, and before it goes.
  virtual void release() = 0;
};

}  // namespace ewa::platform

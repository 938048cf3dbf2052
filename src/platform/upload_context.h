// UploadContext: a GL context sharing another's objects, bound by one worker thread at a time
// to fill buffers while the main context draws.
#pragma once

#include <mutex>

namespace ewa::platform {

class UploadContext {
 public:
  UploadContext() = default;
  virtual ~UploadContext() = default;
  UploadContext(const UploadContext&) = delete;
  UploadContext& operator=(const UploadContext&) = delete;

  // Binds the context to the calling thread, first waiting while another thread has it bound
  // (two uploads at once: the full level's set and a coarse level's). GL calls there go through
  // the function pointers loaded for the context it shares with (one library: the same entry
  // points). Throws ContextError when it cannot be bound.
  void bind() {
    std::unique_lock<std::mutex> lock(mutex_);
    bindNative();
    lock.release();  // held until release()
  }
  // Unbinds it from the calling thread, which bound it: before another thread binds it, and
  // before it goes.
  void release() {
    releaseNative();
    mutex_.unlock();
  }

 protected:
  virtual void bindNative() = 0;
  virtual void releaseNative() = 0;

 private:
  std::mutex mutex_;
};

// Binds an upload context to the calling thread for this object's life (declared before the GL
// objects a worker makes, so those it does not hand out are deleted while it is bound).
class UploadBinding {
 public:
  explicit UploadBinding(UploadContext& context) : context_(context) { context_.bind(); }
  ~UploadBinding() { context_.release(); }
  UploadBinding(const UploadBinding&) = delete;
  UploadBinding& operator=(const UploadBinding&) = delete;

 private:
  UploadContext& context_;
};

}  // namespace ewa::platform

// GlContext: the interface of an OpenGL 4.5 core context (OSMesa, EGL or a GLFW window).
// Deliberately free of GL headers, so UI code next to Dear ImGui's GL loader can include it.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_loader.h"
#include "platform/upload_context.h"

namespace ewa::platform {

// A context could not be created or is not OpenGL 4.5 core; the message is one line, e.g.
// "OSMesa: OpenGL 4.5 core profile not available (got 3.1 Mesa 22.3.6)".
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the context reported about itself when it was created.
struct GlInfo {
  int major = 0;
  int minor = 0;
  bool coreProfile = false;
  std::string version;      // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  std::string renderer;     // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string vendor;       // GL_VENDOR
  std::string glslVersion;  // GL_SHADING_LANGUAGE_VERSION
};

// One OpenGL 4.5 core context. Constructors of the implementations leave the new context
// current with the GL function pointers (gl_api.h) loaded from it. GL objects (gl::Buffer, ...)
// must be destroyed while their context is still alive and current.
class GlContext {
 public:
  virtual ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes the context current on the calling thread and reloads the GL function pointers from
  // it (they are process-wide and may come from another backend's library otherwise).
  void makeCurrent();
  // Address of a GL function of this context (the context should be current), or nullptr.
  virtual void* getProcAddress(const char* name) = 0;
  // A second context sharing this one's objects, for a worker thread to upload data while this
  // one draws (made on this thread, which stays bound here); nullptr where the backend makes
  // none (EGL on a display without surfaceless contexts) or it fails: then uploads run on this
  // thread.
  virtual std::unique_ptr<UploadContext> createUploadContext();
  // One line: "<backend>: OpenGL <GL_VERSION>, <GL_RENDERER>".
  virtual std::string description() const;

  // "OSMesa", "EGL (surfaceless)", "GLFW", ...
  const std::string& backendName() const { return backendName_; }
  const GlInfo& info() const { return info_; }

 protected:
  explicit GlContext(std::string backendName);

  // Binds the native context to the calling thread; throws ContextError on failure.
  virtual void makeNativeCurrent() = 0;
  // For the constructors: makes the context current, reads GlInfo, throws ContextError unless
  // it is OpenGL 4.5+ core with every core function present, then loads the function pointers.
  void initializeGl();
  void setBackendName(std::string name) { backendName_ = std::move(name); }

 private:
  void loadFunctions();

  std::string backendName_;
  GlInfo info_;
};

// Reads GlInfo from the current context through `getProcAddress` alone (usable before the
// loader ran, e.g. to report what an unsuitable context offers). Empty strings when GL fails.
GlInfo queryGlInfo(const gl::ProcLoader& getProcAddress);

}  // namespace ewa::platform

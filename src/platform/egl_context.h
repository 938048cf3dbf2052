// EglContext: a headless OpenGL 4.5 core context through EGL (surfaceless, device or default).
#pragma once

#include "platform/gl_context.h"

namespace ewa::platform {

class EglContext final : public GlContext {
 public:
  // Tries, in order, the displays of EGL_MESA_platform_surfaceless, of each EGL_EXT_platform_device
  // device, then eglGetDisplay(EGL_DEFAULT_DISPLAY), and keeps the first that gives an OpenGL 4.5
  // core context. EWAVIEW_EGL_DEVICE=N tries device N alone; a node-local rank set with
  // setEglLocalRank (egl_device_choice.h) puts that rank's device first. The context has no surface
  // (EGL_KHR_surfaceless_context): render into FBOs. Only on displays without that extension does
  // it fall back to a width x height pbuffer. Leaves the context current. Throws ContextError
  // saying why each display failed.
  EglContext(int width = 16, int height = 16);
  ~EglContext() override;

  void* getProcAddress(const char* name) override;
  // A context sharing this one's objects, surfaceless (none on a display with pbuffers only).
  std::unique_ptr<UploadContext> createUploadContext() override;

 protected:
  void makeNativeCurrent() override;

 private:
  // Tries one display; on failure returns false and says why in `reason`.
  bool tryDisplay(void* display, int width, int height, std::string& reason);
  void destroy();

  // EGLDisplay, EGLContext and EGLSurface are all pointers; <EGL/egl.h> stays in the .cpp.
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
  void* config_ = nullptr;  // EGLConfig
};

}  // namespace ewa::platform

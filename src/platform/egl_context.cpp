// EglContext: EGL display selection, 4.5 core context creation and proc lookup.
#include "platform/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "platform/egl_device_choice.h"

namespace ewa::platform {

namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  size_t length = std::strlen(name);
  for (const char* at = std::strstr(list, name); at; at = std::strstr(at + 1, name)) {
    bool starts = at == list || at[-1] == ' ';
    bool ends = at[length] == '\0' || at[length] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

std::string eglErrorName(EGLint error) {
#define EWA_EGL_ERROR(code) \
  { code, #code }
  static const struct {
    EGLint code;
    const char* name;
  } kNames[] = {
      EWA_EGL_ERROR(EGL_SUCCESS),           EWA_EGL_ERROR(EGL_NOT_INITIALIZED),
      EWA_EGL_ERROR(EGL_BAD_ACCESS),        EWA_EGL_ERROR(EGL_BAD_ALLOC),
      EWA_EGL_ERROR(EGL_BAD_ATTRIBUTE),     EWA_EGL_ERROR(EGL_BAD_CONFIG),
      EWA_EGL_ERROR(EGL_BAD_CONTEXT),       EWA_EGL_ERROR(EGL_BAD_CURRENT_SURFACE),
      EWA_EGL_ERROR(EGL_BAD_DISPLAY),       EWA_EGL_ERROR(EGL_BAD_MATCH),
      EWA_EGL_ERROR(EGL_BAD_NATIVE_PIXMAP), EWA_EGL_ERROR(EGL_BAD_NATIVE_WINDOW),
      EWA_EGL_ERROR(EGL_BAD_PARAMETER),     EWA_EGL_ERROR(EGL_BAD_SURFACE),
      EWA_EGL_ERROR(EGL_CONTEXT_LOST),
  };
#undef EWA_EGL_ERROR
  for (const auto& entry : kNames) {
    if (entry.code == error) return entry.name;
  }
  char text[32];
  std::snprintf(text, sizeof(text), "EGL error 0x%04X", static_cast<unsigned>(error));
  return text;
}

const EGLint kCoreContextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};

// "<call>: EGL_BAD_..." from the calling thread's last EGL error.
std::string failed(const char* call) {
  return std::string(call) + ": " + eglErrorName(eglGetError());
}

// A candidate display and what to call it in messages and in backendName().
struct Candidate {
  EGLDisplay display;
  std::string label;
};

// The EGL devices (EGL_EXT_device_enumeration), none where the extension is missing.
std::vector<EGLDeviceEXT> eglDevices(const char* client) {
  if (!hasExtension(client, "EGL_EXT_platform_device") ||
      !hasExtension(client, "EGL_EXT_device_enumeration"))
    return {};
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  EGLint count = 0;
  if (!queryDevices || !queryDevices(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  if (!queryDevices(count, devices.data(), &count)) return {};
  devices.resize(static_cast<size_t>(count));
  return devices;
}

// Whether each device is a software renderer: Mesa lists its llvmpipe device beside the GPUs,
// and a rank given it by its local rank would draw on the CPU.
std::vector<bool> softwareDevices(const std::vector<EGLDeviceEXT>& devices) {
  auto queryString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
  std::vector<bool> software;
  for (EGLDeviceEXT device : devices)
    software.push_back(queryString && hasExtension(queryString(device, EGL_EXTENSIONS),
                                                   "EGL_MESA_device_software"));
  return software;
}

Candidate deviceCandidate(EGLDeviceEXT device, int index, std::vector<std::string>& reasons,
                          bool& ok) {
  std::string label = "EGL (device " + std::to_string(index) + ")";
  EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
  ok = display != EGL_NO_DISPLAY;
  if (!ok) reasons.push_back(label + ": " + failed("eglGetPlatformDisplay"));
  return {display, label};
}

// The displays to try, in order. EWAVIEW_EGL_DEVICE=N: device N alone (a device named by hand
// that fails is an error, not a reason to draw elsewhere). A node-local rank set
// (setEglLocalRank): its device (eglDeviceForLocalRank) first, then the usual order. Otherwise:
// the surfaceless display, each device, the default display.
std::vector<Candidate> candidateDisplays(std::vector<std::string>& reasons) {
  std::vector<Candidate> candidates;
  // EGL_NO_DISPLAY queries the client extensions (EGL_EXT_client_extensions).
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::vector<EGLDeviceEXT> devices = eglDevices(client);
  std::optional<int> named;
  try {
    named = eglDeviceFromEnvironment();
  } catch (const std::invalid_argument& error) {
    throw ContextError(std::string("EGL: ") + error.what());
  }
  if (named) {
    if (*named >= int(devices.size()))
      throw ContextError("EGL: EWAVIEW_EGL_DEVICE=" + std::to_string(*named) + " but " +
                         (devices.empty()
                              ? std::string("EGL lists no devices")
                              : "EGL lists devices 0 to " + std::to_string(devices.size() - 1)));
    bool ok = false;
    Candidate candidate = deviceCandidate(devices[size_t(*named)], *named, reasons, ok);
    if (ok) candidates.push_back(candidate);
    return candidates;
  }
  int first = -1;
  if (eglLocalRank() >= 0) first = eglDeviceForLocalRank(eglLocalRank(), softwareDevices(devices));
  if (first >= 0) {
    bool ok = false;
    Candidate candidate = deviceCandidate(devices[size_t(first)], first, reasons, ok);
    if (ok) candidates.push_back(candidate);
  }
  if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY)
      candidates.push_back({display, "EGL (surfaceless)"});
    else
      reasons.push_back("surfaceless: " + failed("eglGetPlatformDisplay"));
  }
  for (int i = 0; i < int(devices.size()); ++i) {
    if (i == first) continue;
    bool ok = false;
    Candidate candidate = deviceCandidate(devices[size_t(i)], i, reasons, ok);
    if (ok) candidates.push_back(candidate);
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY)
    candidates.push_back({display, "EGL (default display)"});
  else
    reasons.push_back("default display: " + failed("eglGetDisplay"));
  return candidates;
}

}  // namespace

EglContext::EglContext(int width, int height) : GlContext("EGL") {
  std::vector<std::string> reasons;
  for (const Candidate& candidate : candidateDisplays(reasons)) {
    std::string reason;
    if (!tryDisplay(candidate.display, width, height, reason)) {
      reasons.push_back(candidate.label + ": " + reason);
      continue;
    }
    setBackendName(candidate.label);
    try {
      initializeGl();
      return;
    } catch (const ContextError& error) {
      reasons.push_back(error.what());
      destroy();
    }
  }
  std::string message = "EGL: no display gives an OpenGL 4.5 core context";
  for (size_t i = 0; i < reasons.size(); ++i) message += (i ? "; " : " (") + reasons[i];
  throw ContextError(message + (reasons.empty() ? "" : ")"));
}

EglContext::~EglContext() {
  destroy();
}

bool EglContext::tryDisplay(void* display, int width, int height, std::string& reason) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    reason = failed("eglInitialize");
    return false;
  }
  // Displays are not terminated on failure or in destroy(): eglTerminate acts on the whole
  // process's display, so it would also kill other EglContexts on it (Mesa 22 has no
  // EGL_KHR_display_reference to count users).
  if (!eglBindAPI(EGL_OPENGL_API)) {
    reason = failed("eglBindAPI(EGL_OPENGL_API)");
    return false;
  }
  bool surfaceless =
      hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                     surfaceless ? 0 : EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configs) || configs < 1) {
    reason = configs < 1 ? "no EGL config for desktop OpenGL" : failed("eglChooseConfig");
    return false;
  }
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, kCoreContextAttributes);
  if (context == EGL_NO_CONTEXT) {
    reason = "OpenGL 4.5 core profile not available (" + failed("eglCreateContext") + ")";
    return false;
  }
  EGLSurface surface = EGL_NO_SURFACE;
  if (!surfaceless) {
    const EGLint pbufferAttributes[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbufferAttributes);
    if (surface == EGL_NO_SURFACE) {
      reason = failed("eglCreatePbufferSurface");
      eglDestroyContext(display, context);
      return false;
    }
  }
  display_ = display;
  context_ = context;
  surface_ = surface;
  config_ = config;
  return true;
}

namespace {

class EglUploadContext final : public UploadContext {
 public:
  EglUploadContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~EglUploadContext() override { eglDestroyContext(display_, context_); }
  void bindNative() override {
    if (!eglBindAPI(EGL_OPENGL_API) ||
        !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw ContextError("EGL: cannot bind the upload context (" + failed("eglMakeCurrent") + ")");
  }
  void releaseNative() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

}  // namespace

std::unique_ptr<UploadContext> EglContext::createUploadContext() {
  if (surface_ != EGL_NO_SURFACE) return nullptr;  // a pbuffer display: no surfaceless binds
  EGLContext shared = eglCreateContext(display_, config_, context_, kCoreContextAttributes);
  if (shared == EGL_NO_CONTEXT) return nullptr;
  return std::make_unique<EglUploadContext>(display_, shared);
}

void EglContext::makeNativeCurrent() {
  if (!eglBindAPI(EGL_OPENGL_API) || !eglMakeCurrent(display_, surface_, surface_, context_)) {
    throw ContextError(backendName() + ": " + failed("eglMakeCurrent"));
  }
}

void* EglContext::getProcAddress(const char* name) {
  return reinterpret_cast<void*>(eglGetProcAddress(name));
}

void EglContext::destroy() {
  if (!display_) return;
  if (eglGetCurrentContext() == context_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  display_ = context_ = surface_ = nullptr;
}

}  // namespace ewa::platform

// OsMesaContext: OSMesa context creation with a 4.5 core profile request, and its proc lookup.
// This file includes <GL/osmesa.h> (and so <GL/gl.h>), hence never gl_api.h.
#include "platform/osmesa_context.h"

#include <GL/osmesa.h>

#include <memory>
#include <string>
#include <vector>

namespace ewa::platform {

namespace {

// Creates a throwaway default context to tell the user what OSMesa offers instead of 4.5 core.
std::string offeredVersion() {
  OSMesaContext probe = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!probe) return "no context at all";
  std::vector<unsigned char> pixels(4 * 4 * 4);
  std::string version = "unknown version";
  if (OSMesaMakeCurrent(probe, pixels.data(), GL_UNSIGNED_BYTE, 4, 4)) {
    GlInfo info = queryGlInfo(
        [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
    if (!info.version.empty()) version = info.version;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
  OSMesaDestroyContext(probe);
  return version;
}

const int kCoreAttributes[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               24,
                               OSMESA_STENCIL_BITS,
                               8,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               4,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               5,
                               0};

class OsMesaUploadContext final : public UploadContext {
 public:
  explicit OsMesaUploadContext(OSMesaContext context) : context_(context), pixels_(4 * 4 * 4) {}
  ~OsMesaUploadContext() override { OSMesaDestroyContext(context_); }
  void bindNative() override {
    if (!OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, 4, 4))
      throw ContextError("OSMesa: cannot bind the upload context");
  }
  void releaseNative() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

 private:
  OSMesaContext context_;
  std::vector<unsigned char> pixels_;
};

}  // namespace

OsMesaContext::OsMesaContext(int width, int height)
    : GlContext("OSMesa"),
      width_(width),
      height_(height),
      buffer_(static_cast<size_t>(width > 0 ? width : 0) * (height > 0 ? height : 0) * 4) {
  if (width <= 0 || height <= 0) {
    throw ContextError("OSMesa: invalid buffer size " + std::to_string(width) + "x" +
                       std::to_string(height));
  }
  context_ = OSMesaCreateContextAttribs(kCoreAttributes, nullptr);
  if (!context_) {
    throw ContextError("OSMesa: OpenGL 4.5 core profile not available (got " + offeredVersion() +
                       ")");
  }
  try {
    initializeGl();
  } catch (...) {
    destroy();  // the destructor does not run when the constructor throws
    throw;
  }
}

OsMesaContext::~OsMesaContext() {
  destroy();
}

void OsMesaContext::makeNativeCurrent() {
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
    throw ContextError("OSMesa: OSMesaMakeCurrent failed");
  }
}

std::unique_ptr<UploadContext> OsMesaContext::createUploadContext() {
  OSMesaContext shared = OSMesaCreateContextAttribs(kCoreAttributes, context_);
  if (!shared) return nullptr;
  return std::make_unique<OsMesaUploadContext>(shared);
}

void* OsMesaContext::getProcAddress(const char* name) {
  return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

void OsMesaContext::destroy() {
  if (!context_) return;
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
  context_ = nullptr;
}

}  // namespace ewa::platform

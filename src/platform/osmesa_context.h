// OsMesaContext: an off-screen OpenGL 4.5 core context from Mesa's OSMesa (software, no display).
#pragma once

#include <memory>
#include <vector>

#include "platform/gl_context.h"

struct osmesa_context;  // OSMesa's opaque context; <GL/osmesa.h> stays out of this header

namespace ewa::platform {

class OsMesaContext final : public GlContext {
 public:
  // Creates and makes current a 4.5 core context drawing into a width x height RGBA8 buffer.
  // That buffer is only the default framebuffer: real rendering goes to FBOs, so it can be
  // small. Throws ContextError when OSMesa cannot provide OpenGL 4.5 core.
  OsMesaContext(int width = 16, int height = 16);
  ~OsMesaContext() override;

  void* getProcAddress(const char* name) override;
  // A context sharing this one's objects, bound to a 4x4 buffer of its own.
  std::unique_ptr<UploadContext> createUploadContext() override;

 protected:
  void makeNativeCurrent() override;

 private:
  void destroy();

  osmesa_context* context_ = nullptr;
  int width_;
  int height_;
  std::vector<unsigned char> buffer_;  // the default framebuffer's pixels
};

}  // namespace ewa::platform

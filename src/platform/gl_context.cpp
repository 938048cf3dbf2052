// GlContext: the version check and function loading shared by every context backend.
#include "platform/gl_context.h"

#include <cstdio>

#include "gl/gl_api.h"

namespace ewa::platform {

namespace {

std::string glString(PFNGLGETSTRINGPROC getString, GLenum name) {
  const GLubyte* text = getString ? getString(name) : nullptr;
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

GlInfo queryGlInfo(const gl::ProcLoader& getProcAddress) {
  // Only two entry points, resolved by hand: the full loader may fail on an old context.
  auto getString = reinterpret_cast<PFNGLGETSTRINGPROC>(getProcAddress("glGetString"));
  auto getIntegerv = reinterpret_cast<PFNGLGETINTEGERVPROC>(getProcAddress("glGetIntegerv"));
  GlInfo info;
  info.version = glString(getString, GL_VERSION);
  info.renderer = glString(getString, GL_RENDERER);
  info.vendor = glString(getString, GL_VENDOR);
  info.glslVersion = glString(getString, GL_SHADING_LANGUAGE_VERSION);
  // GL_VERSION starts with "<major>.<minor>" in every desktop GL; GL_MAJOR_VERSION needs 3.0.
  if (std::sscanf(info.version.c_str(), "%d.%d", &info.major, &info.minor) != 2) {
    info.major = info.minor = 0;
  }
  if (getIntegerv && (info.major > 3 || (info.major == 3 && info.minor >= 2))) {
    GLint mask = 0;
    getIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    info.coreProfile = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
  }
  return info;
}

GlContext::GlContext(std::string backendName) : backendName_(std::move(backendName)) {}

GlContext::~GlContext() = default;

void GlContext::makeCurrent() {
  makeNativeCurrent();
  loadFunctions();
}

std::unique_ptr<UploadContext> GlContext::createUploadContext() {
  return nullptr;
}

std::string GlContext::description() const {
  return backendName_ + ": OpenGL " + info_.version + ", " + info_.renderer;
}

void GlContext::initializeGl() {
  makeNativeCurrent();
  info_ = queryGlInfo([this](const char* name) { return getProcAddress(name); });
  bool recent = info_.major > 4 || (info_.major == 4 && info_.minor >= 5);
  if (!recent || !info_.coreProfile) {
    std::string got = info_.version.empty() ? "no GL_VERSION" : info_.version;
    if (recent) got += ", not a core profile";
    throw ContextError(backendName_ + ": OpenGL 4.5 core profile not available (got " + got + ")");
  }
  loadFunctions();
}

void GlContext::loadFunctions() {
  std::string missing;
  if (!gl::loadGlFunctions([this](const char* name) { return getProcAddress(name); }, &missing)) {
    throw ContextError(backendName_ + ": " + missing);
  }
}

}  // namespace ewa::platform

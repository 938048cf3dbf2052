// GL error and framebuffer status names, and the glGetError check.
#include "gl/gl_error.h"

#include <cstdio>

namespace ewa::gl {

namespace {

struct CodeName {
  GLenum code;
  const char* name;
};

#define EWA_GL_NAME(code) \
  { code, #code }
const CodeName kErrors[] = {
    EWA_GL_NAME(GL_NO_ERROR),
    EWA_GL_NAME(GL_INVALID_ENUM),
    EWA_GL_NAME(GL_INVALID_VALUE),
    EWA_GL_NAME(GL_INVALID_OPERATION),
    EWA_GL_NAME(GL_INVALID_FRAMEBUFFER_OPERATION),
    EWA_GL_NAME(GL_OUT_OF_MEMORY),
    EWA_GL_NAME(GL_STACK_UNDERFLOW),
    EWA_GL_NAME(GL_STACK_OVERFLOW),
    EWA_GL_NAME(GL_CONTEXT_LOST),
};
const CodeName kFramebufferStatuses[] = {
    EWA_GL_NAME(GL_FRAMEBUFFER_COMPLETE),
    EWA_GL_NAME(GL_FRAMEBUFFER_UNDEFINED),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER),
    EWA_GL_NAME(GL_FRAMEBUFFER_UNSUPPORTED),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE),
    EWA_GL_NAME(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS),
};
#undef EWA_GL_NAME

// The table's name for `code`, else "<fallback> 0x1234".
template <size_t N>
std::string nameOf(const CodeName (&table)[N], GLenum code, const char* fallback) {
  for (const CodeName& entry : table) {
    if (entry.code == code) return entry.name;
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%s 0x%04X", fallback, static_cast<unsigned>(code));
  return text;
}

}  // namespace

std::string glErrorString(GLenum error) {
  return nameOf(kErrors, error, "GL error");
}

std::string framebufferStatusString(GLenum status) {
  return nameOf(kFramebufferStatuses, status, "framebuffer status");
}

void checkGlError(const char* where) {
  // Several flags can be pending at once; a bounded loop also guards against a lost context
  // that keeps reporting errors.
  std::string errors;
  for (int i = 0; i < 16; ++i) {
    GLenum error = glGetError();
    if (error == GL_NO_ERROR) break;
    errors += (errors.empty() ? "" : ", ") + glErrorString(error);
  }
  if (!errors.empty()) throw GlError(std::string("GL error at ") + where + ": " + errors);
}

}  // namespace ewa::gl

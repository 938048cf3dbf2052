// GlError, the exception every GL wrapper throws, and helpers that turn GL status codes into text.
#pragma once

#include <stdexcept>
#include <string>

#include "gl/gl_api.h"

namespace ewa::gl {

// A GL call, shader build or framebuffer check failed; the message says what and where.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "GL_INVALID_ENUM", ... ; "GL error 0x1234" for codes it does not know.
std::string glErrorString(GLenum error);

// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT", ... ; "GL_FRAMEBUFFER_COMPLETE" for success.
std::string framebufferStatusString(GLenum status);

// Drains glGetError; throws GlError("GL error at <where>: GL_INVALID_OPERATION, ...") when any
// error was pending. Cheap enough for setup code; avoid it in per-frame hot loops.
void checkGlError(const char* where);

}  // namespace ewa::gl

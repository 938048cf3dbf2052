// The GL function loader's entry point, without GL headers, so context code can call it anywhere.
#pragma once

#include <functional>
#include <string>

namespace ewa::gl {

// Returns the address of a GL function of the current context, or nullptr.
using ProcLoader = std::function<void*(const char*)>;

// Fills every GL 1.0-4.5 core function pointer (ewa_glFoo, used through the glFoo macros of
// gl_api.h) from `loader`; the context must be current. Returns false when some function is
// missing and then, when `error` is given, names the missing functions in it. The pointers are
// process-wide: after switching to a context of another backend, load again (GlContext's
// makeCurrent does).
bool loadGlFunctions(const ProcLoader& loader, std::string* error = nullptr);

}  // namespace ewa::gl

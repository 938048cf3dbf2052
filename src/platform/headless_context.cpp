// Headless context factory: maps a backend name to an OSMesa or EGL context.
#include "platform/headless_context.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <stdexcept>

#include "platform/egl_context.h"
#include "platform/osmesa_context.h"

namespace ewa::platform {

std::unique_ptr<GlContext> createHeadlessContext(HeadlessBackend backend, int width, int height) {
  switch (backend) {
    case HeadlessBackend::OsMesa:
      return std::make_unique<OsMesaContext>(width, height);
    case HeadlessBackend::Egl:
      return std::make_unique<EglContext>(width, height);
  }
  throw std::invalid_argument("createHeadlessContext: unknown backend");
}

HeadlessBackend parseHeadlessBackend(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "osmesa") return HeadlessBackend::OsMesa;
  if (lower == "egl") return HeadlessBackend::Egl;
  throw std::invalid_argument("unknown headless backend \"" + name + "\" (expected osmesa or egl)");
}

const char* headlessBackendName(HeadlessBackend backend) {
  return backend == HeadlessBackend::OsMesa ? "osmesa" : "egl";
}

std::vector<std::string> headlessBackendNames() {
  return {headlessBackendName(HeadlessBackend::OsMesa), headlessBackendName(HeadlessBackend::Egl)};
}

std::string defaultHeadlessBackend() {
  const char* value = std::getenv("EWAVIEW_BACKEND");
  if (!value || !*value) return "osmesa";
  try {
    return headlessBackendName(parseHeadlessBackend(value));
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("EWAVIEW_BACKEND=\"" + std::string(value) +
                                "\": expected osmesa or egl");
  }
}

}  // namespace ewa::platform

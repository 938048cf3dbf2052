// The program's version string, from the CMake project version.
#include "app/version.h"

namespace ewa {
const char* versionString() {
  return EWA_VERSION;
}
}  // namespace ewa

// The program's version string, shared by --version and --info.
#pragma once

namespace ewa {
const char* versionString();
}

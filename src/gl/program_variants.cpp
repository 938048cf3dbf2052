// Keys and #define lines of program variants.
#include "gl/program_variants.h"

namespace ewa::gl {

unsigned variantKey(const VariantFlags& flags) {
  unsigned key = 0;
  for (size_t i = 0; i < flags.size() && i < 32; ++i)
    if (flags[i].second) key |= 1u << i;
  return key;
}

std::string variantDefines(const VariantFlags& flags) {
  std::string text;
  for (const auto& [name, on] : flags)
    text += std::string("#define ") + name + (on ? " 1\n" : " 0\n");
  return text;
}

}  // namespace ewa::gl

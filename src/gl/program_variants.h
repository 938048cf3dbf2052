// ProgramVariants: programs of one shader set compiled per variant (a set of compile-time
// switches, #define NAME 0|1) on first use, so each frame runs only the code it needs.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ewa::gl {

// A variant's switches, in a fixed order: name and value.
using VariantFlags = std::vector<std::pair<const char*, bool>>;
// One bit a switch, in order (at most 32 switches).
unsigned variantKey(const VariantFlags& flags);
// "#define NAME 1\n" or "... 0\n" a switch, in order.
std::string variantDefines(const VariantFlags& flags);

template <class Programs>
class ProgramVariants {
 public:
  // The programs of `flags`, built by build(variantDefines(flags)) the first time; the
  // reference stays valid while this object lives (map nodes stay put).
  template <class Build>
  Programs& select(const VariantFlags& flags, Build&& build) {
    const unsigned key = variantKey(flags);
    auto found = programs_.find(key);
    if (found == programs_.end())
      found = programs_.emplace(key, build(variantDefines(flags))).first;
    return found->second;
  }
  size_t compiled() const { return programs_.size(); }

 private:
  std::map<unsigned, Programs> programs_;
};

}  // namespace ewa::gl

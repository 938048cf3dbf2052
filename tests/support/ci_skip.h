// Skips that CI refuses: a missing OpenGL 4.5, EGL or display skips a test on a developer's
// machine (with the reason) but fails it when CI=true, so CI never passes by skipping.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace ewa::test {

// True when the environment says this is a CI run: CI set to anything but "", "0" or "false".
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  if (!ci) return false;
  const std::string v = ci;
  return !(v.empty() || v == "0" || v == "false");
}

}  // namespace ewa::test

// Use as a statement: `if (!context) EWA_SKIP_UNLESS_CI() << reason;`. Outside CI it skips
// (GTEST_SKIP) with the reason; with CI=true it fails the test with the same message.
#define EWA_SKIP_UNLESS_CI()                                 \
  switch (0)                                                 \
  case 0:                                                    \
  default:                                                   \
    if (!::ewa::test::runningInCi())                         \
      GTEST_SKIP() << "skipped (would fail with CI=true): "; \
    else                                                     \
      GTEST_FAIL() << "CI=true and this test cannot run: "

// The program's version is the newest release CHANGELOG.md names.
#include "app/version.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

namespace ewa {
namespace {

TEST(Version, IsTheChangelogsNewestRelease) {
  std::ifstream in(std::string(EWA_SOURCE_DIR) + "/CHANGELOG.md");
  ASSERT_TRUE(in) << "CHANGELOG.md missing";
  const std::regex release(R"(^## \[(\d+\.\d+\.\d+)\].*)");
  std::string line;
  std::smatch match;
  while (std::getline(in, line))
    if (std::regex_match(line, match, release)) break;
  ASSERT_FALSE(match.empty()) << "CHANGELOG.md has no \"## [X.Y.Z]\" heading";
  EXPECT_EQ(match[1].str(), versionString())
      << "CMakeLists.txt's project(VERSION) and CHANGELOG.md's newest release differ";
}

}  // namespace
}  // namespace ewa

// docs/user/options.md and keys.md are the pages the option and key tables generate.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/option_table.h"
#include "app/options.h"
#include "app/options_markdown.h"
#include "render/renderer.h"
#include "ui/keys_markdown.h"

namespace ewa {
namespace {

std::string committed(const std::string& name) {
  std::ifstream in(std::string(EWA_SOURCE_DIR) + "/docs/user/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

constexpr const char* kRegenerate =
    " differs from what the tables generate: regenerate it with "
    "`cmake --build build --target ewaview-docs && build/ewaview-docs docs/user` and commit it";

TEST(DocsPages, OptionsPageIsGenerated) {
  EXPECT_TRUE(optionsMarkdown() == committed("options.md"))
      << "docs/user/options.md" << kRegenerate;
}

TEST(DocsPages, KeysPageIsGenerated) {
  EXPECT_TRUE(keysMarkdown() == committed("keys.md")) << "docs/user/keys.md" << kRegenerate;
}

TEST(DocsPages, OptionsPageStatesTheCodesDefaults) {
  const std::string page = optionsMarkdown();
  EXPECT_NE(page.find("| `--kernel-width` | `S`: 0.3 to 2 | `" +
                      numberText(RenderSettings{}.kernelWidth) + "` |"),
            std::string::npos);
  EXPECT_NE(
      page.find("| `--cutoff` | `C`: 0.25 to 64 | `" + numberText(RenderSettings{}.cutoff) + "` |"),
      std::string::npos);
  for (OptionGroup group : kOptionGroups)
    EXPECT_NE(page.find(std::string("\n## ") + optionGroupTitle(group) + "\n"), std::string::npos);
}

}  // namespace
}  // namespace ewa

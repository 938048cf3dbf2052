// docs/user/options.md from the option table: the page is generated, never edited by hand.
#include "app/options_markdown.h"

#include <sstream>

#include "app/option_table.h"

namespace ewa {

namespace {

// A table cell: a '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string code(const std::string& text) {
  return "`" + text + "`";
}

std::string nameText(const OptionSpec& spec) {
  if (spec.name.rfind("--", 0) != 0) return code("FILE");  // the positional
  return spec.shortName.empty() ? code(spec.name)
                                : code("-" + spec.shortName) + ", " + code(spec.name);
}

std::string valueText(const OptionSpec& spec) {
  std::string text;
  for (const std::string& c : spec.choices) text += (text.empty() ? "" : ", ") + code(c);
  if (!spec.valueName.empty() && spec.name.rfind("--", 0) == 0)
    text += (text.empty() ? "" : ", ") + code(spec.valueName);
  if (const std::string range = spec.rangeText(); !range.empty()) text += ": " + range;
  return text;
}

}  // namespace

std::string optionsMarkdown() {
  std::ostringstream out;
  out << "# ewaview's options\n\n"
      << "<!-- Generated from src/app/option_table.cpp by `build/ewaview-docs docs/user`: edit "
         "the table, not this page. -->\n\n"
      << "`ewaview [FILE] [OPTIONS]`: without `--output` it opens a window, with `--output` it "
         "renders headless and exits. `ewaview --help` lists the same options in short. In "
         "Python (`ewaview.Scene(path, **options)`, `render(**options)`) an option is a keyword, "
         "`_` for `-` (`kernel_width=0.5`, a flag `shading=True`), but for these, which the "
         "module does itself or cannot do:";
  bool first = true;
  for (const OptionSpec& spec : optionTable()) {
    if (spec.python) continue;
    out << (first ? " " : ", ") << code(spec.keyword());
    first = false;
  }
  out << ".\n";
  for (OptionGroup group : kOptionGroups) {
    out << "\n## " << optionGroupTitle(group) << "\n\n"
        << "| option | value | default | meaning |\n| --- | --- | --- | --- |\n";
    for (const OptionSpec& spec : optionTable())
      if (spec.group == group)
        out << "| " << nameText(spec) << " | " << cell(valueText(spec)) << " | "
            << (spec.defaultText.empty() ? "" : cell(code(spec.defaultText))) << " | "
            << cell(spec.help) << " |\n";
    for (const OptionSpec& spec : optionTable())
      if (spec.group == group && !spec.longHelp.empty())
        out << "\n" << nameText(spec) << ": " << spec.longHelp << "\n";
  }
  return out.str();
}

}  // namespace ewa

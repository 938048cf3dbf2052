// CLI11 options made from the option table's rows, and --help in the table's groups.
#include "app/option_binding.h"

#include <algorithm>
#include <sstream>

namespace ewa {

namespace {

// What --help shows after the name: the value's name, else the choices ("on|off").
std::string valueText(const OptionSpec& spec) {
  std::string text;
  for (const std::string& c : spec.choices) text += (text.empty() ? "" : "|") + c;
  if (!spec.valueName.empty()) text += (text.empty() ? "" : "|") + spec.valueName;
  return text;
}

CLI::Validator choicesCheck(const OptionSpec& spec, bool integer) {
  if (!integer) return CLI::IsMember(spec.choices);
  std::vector<int> numbers;
  for (const std::string& c : spec.choices) numbers.push_back(std::stoi(c));
  return CLI::IsMember(numbers);
}

CLI::Validator rangeCheck(const OptionSpec& spec, bool integer) {
  if (integer) return CLI::Range(int(*spec.min), int(*spec.max));
  return CLI::Range(*spec.min, *spec.max);
}

}  // namespace

void applyOptionSpec(CLI::Option* option, const OptionSpec& spec, bool integer) {
  option->description(spec.description());
  option->group(optionGroupTitle(spec.group));
  if (spec.name.rfind("--", 0) == 0) option->option_text(valueText(spec));
  const bool ranged = spec.min && spec.max;
  if (!spec.choices.empty() && ranged)
    option->check(choicesCheck(spec, false) | rangeCheck(spec, false));  // "auto" or a number
  else if (!spec.choices.empty())
    option->check(choicesCheck(spec, integer));
  else if (ranged)
    option->check(rangeCheck(spec, integer));
}

CLI::Option* addTableFlag(CLI::App& app, const std::string& name, bool& target) {
  const OptionSpec& spec = optionSpec(name);
  CLI::Option* option = app.add_flag(spec.cliName(), target);
  applyOptionSpec(option, spec, false);
  return option;
}

void addHelpAndVersion(CLI::App& app, const std::string& versionText) {
  const OptionSpec& help = optionSpec("--help");
  app.set_help_flag(help.cliName(), help.description())->group(optionGroupTitle(help.group));
  const OptionSpec& version = optionSpec("--version");
  app.set_version_flag(version.cliName(), versionText, version.description())
      ->group(optionGroupTitle(version.group));
}

std::string GroupedHelpFormatter::make_help(const CLI::App* app, std::string name,
                                            CLI::AppFormatMode mode) const {
  if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
  // Each option's place in the table: within a group, --help keeps the table's order.
  auto rank = [](const CLI::Option* option) {
    const std::vector<OptionSpec>& table = optionTable();
    for (size_t i = 0; i < table.size(); ++i)
      if (option->check_name(table[i].name)) return i;
    return table.size();
  };
  std::ostringstream out;
  out << make_description(app) << make_usage(app, name) << make_positionals(app);
  for (OptionGroup group : kOptionGroups) {
    const std::string title = optionGroupTitle(group);
    std::vector<const CLI::Option*> options = app->get_options([&](const CLI::Option* option) {
      return option->get_group() == title && option->nonpositional();
    });
    std::stable_sort(options.begin(), options.end(),
                     [&](const CLI::Option* a, const CLI::Option* b) { return rank(a) < rank(b); });
    if (!options.empty()) out << make_group(title, false, options);
  }
  out << "\n" << make_footer(app);
  return out.str();
}

}  // namespace ewa

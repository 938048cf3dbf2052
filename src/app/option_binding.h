// Adds options to a CLI11 app from their rows in the option table: the name, help, group,
// value name and checks (choices, range) come from the row, the variable from the caller.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "app/option_table.h"

namespace ewa {

// Sets an option's help, group, value text and checks from its row. `integer`: the option holds
// whole numbers (its range and choices are checked as such, with CLI11's messages for them).
void applyOptionSpec(CLI::Option* option, const OptionSpec& spec, bool integer);

namespace detail {
template <typename T>
struct OptionValue {
  using type = T;
};
template <typename T>
struct OptionValue<std::vector<T>> {
  using type = T;
};
template <typename T>
struct OptionValue<std::optional<T>> {
  using type = T;
};
}  // namespace detail

// The option `name` ("--kernel-width", or "file" for the positional) reading into `target`.
template <typename T>
CLI::Option* addTableOption(CLI::App& app, const std::string& name, T& target) {
  const OptionSpec& spec = optionSpec(name);
  CLI::Option* option = app.add_option(spec.cliName(), target);
  using Value = typename detail::OptionValue<T>::type;
  applyOptionSpec(option, spec, std::is_integral_v<Value>);
  return option;
}

// The flag `name` ("--shading") setting `target`.
CLI::Option* addTableFlag(CLI::App& app, const std::string& name, bool& target);

// --help and --version from their rows.
void addHelpAndVersion(CLI::App& app, const std::string& versionText);

// A --help that prints the options in the table's groups and order (CLI11 prints groups in the
// order their first options were added).
class GroupedHelpFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override;
};

}  // namespace ewa

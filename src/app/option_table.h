// The command line's options, each described once: the parse (CLI11), --help, the benchmark
// programs' shared options, the Python module's keywords and docs/user/options.md read this table.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ewa {

// --help's sections and the options page's, in this order.
enum class OptionGroup {
  Input,
  Output,
  Camera,
  TransferFunction,
  Rendering,
  Shading,
  ShearWarp,
  Advanced
};
constexpr OptionGroup kOptionGroups[] = {OptionGroup::Input,     OptionGroup::Output,
                                         OptionGroup::Camera,    OptionGroup::TransferFunction,
                                         OptionGroup::Rendering, OptionGroup::Shading,
                                         OptionGroup::ShearWarp, OptionGroup::Advanced};
const char* optionGroupTitle(OptionGroup group);  // "Input", "Transfer function", ...

// One option. The setters chain, so each row of the table reads as one statement.
struct OptionSpec {
  std::string name;       // "--kernel-width"; "file" for the positional
  std::string shortName;  // "o" for -o; empty: none
  OptionGroup group = OptionGroup::Advanced;
  std::string valueName;             // "S", "X,Y,Z"; empty: a flag, or one of `choices`
  std::vector<std::string> choices;  // the words it accepts (from the parser's name tables)
  std::optional<double> min, max;    // the range its numbers must lie in
  std::string defaultText;           // read from the settings' defaults; empty: none
  std::string help;                  // one line for --help and the page's table
  std::string longHelp;              // markdown below the page's table; may be empty
  bool python = true;                // the Python module takes it as a keyword

  OptionSpec& shortLetter(std::string s) { return shortName = std::move(s), *this; }
  OptionSpec& value(std::string v) { return valueName = std::move(v), *this; }
  OptionSpec& accepts(std::vector<std::string> c) { return choices = std::move(c), *this; }
  OptionSpec& range(double lo, double hi) { return min = lo, max = hi, *this; }
  OptionSpec& defaultsTo(std::string d) { return defaultText = std::move(d), *this; }
  OptionSpec& describe(std::string h) { return help = std::move(h), *this; }
  OptionSpec& explain(std::string h) { return longHelp = std::move(h), *this; }
  OptionSpec& notInPython() { return python = false, *this; }

  // "-o,--output" as CLI11 takes it.
  std::string cliName() const;
  // The keyword the Python module takes for it: "kernel_width".
  std::string keyword() const;
  // "0.3 to 2", "1 and up"; empty without a range.
  std::string rangeText() const;
  // --help's line: the help, its range and its default.
  std::string description() const;
};

// Every option of ewaview, in --help's order.
const std::vector<OptionSpec>& optionTable();
// The row of `name` ("--kernel-width"); throws std::logic_error for a name the table lacks, so
// an option the parser adds without a row fails every run at once.
const OptionSpec& optionSpec(const std::string& name);
// The row whose Python keyword is `keyword`, or null.
const OptionSpec* optionForKeyword(const std::string& keyword);

}  // namespace ewa

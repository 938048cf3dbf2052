// Keyword options turned into command-line words and parsed by parseCommandLine.
#include "python/python_options.h"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "app/option_table.h"

namespace py = pybind11;

namespace ewa::python {

namespace {

// Collects what parseCommandLine writes to std::cerr while it lives.
class CerrCapture {
 public:
  CerrCapture() : old_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CerrCapture() { std::cerr.rdbuf(old_); }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* old_;
};

std::string trimMessage(std::string m) {
  while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
  const std::string prefix = "ewaview: ", hint = " (see --help)";
  if (m.rfind(prefix, 0) == 0) m.erase(0, prefix.size());
  if (m.size() >= hint.size() && m.compare(m.size() - hint.size(), hint.size(), hint) == 0)
    m.erase(m.size() - hint.size());
  return m;
}

std::string valueWord(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value)) {
    std::string joined;
    for (const py::handle item : value) {
      if (!joined.empty()) joined += ',';
      joined += py::str(item).cast<std::string>();
    }
    return joined;
  }
  return py::str(value).cast<std::string>();
}

}  // namespace

bool isLoadOption(const std::string& key) {
  return key == "synthetic" || key == "tf" || key == "tf_preset" || key == "spacing" ||
         key.rfind("raw_", 0) == 0;
}

std::vector<std::string> optionWords(const py::dict& options) {
  std::vector<std::string> words;
  for (const auto& [k, value] : options) {
    const std::string key = py::str(k).cast<std::string>();
    // What the module does itself (render() instead of --output and --turntable) or cannot do:
    // the option table's rows marked so. A keyword with no row is left to the parser's message.
    if (const OptionSpec* spec = optionForKeyword(key); spec && !spec->python)
      throw UsageError(key + ": not an option of the Python module");
    // NumPy's bool (from comparisons on arrays) counts as a bool too.
    const bool isBool = py::isinstance<py::bool_>(value) ||
                        std::string(Py_TYPE(value.ptr())->tp_name) == "numpy.bool_";
    if (value.is_none() || (isBool && !PyObject_IsTrue(value.ptr()))) continue;
    if (key == "clip_planes") {
      // A list of planes (each PX,PY,PZ,NX,NY,NZ): one --clip-plane per plane.
      if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value))
        throw UsageError("clip_planes: a list of (px, py, pz, nx, ny, nz) planes");
      for (const py::handle plane : value) words.push_back("--clip-plane=" + valueWord(plane));
      continue;
    }
    if (key == "tf_preset" && !py::isinstance<py::str>(value) &&
        py::isinstance<py::sequence>(value)) {
      // A list of presets, applied in order: one --tf-preset each.
      for (const py::handle preset : value) words.push_back("--tf-preset=" + valueWord(preset));
      continue;
    }
    std::string name = "--" + key;
    std::replace(name.begin(), name.end(), '_', '-');
    if (isBool) {
      words.push_back(name);  // a flag
    } else {
      // One word, so a negative first number is not taken for an option.
      words.push_back(name + "=" + valueWord(value));
    }
  }
  return words;
}

Options parseOptionWords(const std::vector<std::string>& words) {
  std::vector<const char*> argv{"ewaview"};
  for (const std::string& w : words) argv.push_back(w.c_str());
  Options options;
  ParseResult result;
  std::string message;
  {
    CerrCapture capture;
    result = parseCommandLine(int(argv.size()), argv.data(), &options);
    message = capture.text();
  }
  if (!result.run) throw UsageError(trimMessage(message.empty() ? "invalid options" : message));
  return options;
}

}  // namespace ewa::python

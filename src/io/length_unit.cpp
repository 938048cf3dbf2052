// lengthUnitName: the spellings NIfTI, NRRD and ImageJ files use for their length units.
#include "io/length_unit.h"

#include <algorithm>
#include <cctype>

namespace ewa {

std::string lengthUnitName(const std::string& text) {
  std::string t = text;
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
  t.erase(0, t.find_first_not_of(" \t"));
  if (t.empty() || t.size() > 16) return "";
  std::string lower = t;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  const std::string micro = "\xC2\xB5", mu = "\xCE\xBC";  // MICRO SIGN, GREEK SMALL LETTER MU
  if (lower == "mm" || lower == "millimeter" || lower == "millimeters" || lower == "millimetre" ||
      lower == "millimetres")
    return "mm";
  if (lower == "um" || lower == "micron" || lower == "microns" || lower == "micrometer" ||
      lower == "micrometers" || lower == "micrometre" || lower == "micrometres" ||
      lower == micro + "m" || lower == mu + "m")
    return "\xC2\xB5m";
  if (lower == "nm" || lower == "nanometer" || lower == "nanometers") return "nm";
  if (lower == "cm" || lower == "centimeter" || lower == "centimeters") return "cm";
  if (lower == "m" || lower == "meter" || lower == "meters" || lower == "metre") return "m";
  // Anything else printable (ASCII letters, digits, a few signs) is kept as written.
  for (const unsigned char c : t)
    if (!std::isalnum(c) && c != ' ' && c != '.' && c != '-' && c != '_' && c != '/') return "";
  return t;
}

}  // namespace ewa

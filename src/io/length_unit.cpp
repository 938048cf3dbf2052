// lengthUnitName: the spellings NIfTI, NRRD, ImageJ and OME files use for their length units.
#include "io/length_unit.h"

#include <cctype>

#include "io/text_fields.h"

namespace ewa {

std::string lengthUnitName(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty() || t.size() > 16) return "";
  const std::string lower = toLower(t);
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
  if (lower == "pm" || lower == "picometer" || lower == "picometers") return "pm";
  // Å (MRC's and OME's unit), as LATIN CAPITAL A WITH RING or ANGSTROM SIGN, or spelled out.
  if (t == "\xC3\x85" || t == "\xE2\x84\xAB" || lower == "angstrom" || lower == "angstroms")
    return "\xC3\x85";
  // Anything else printable (ASCII letters, digits, a few signs) is kept as written.
  for (const unsigned char c : t)
    if (!std::isalnum(c) && c != ' ' && c != '.' && c != '-' && c != '_' && c != '/') return "";
  return t;
}

}  // namespace ewa

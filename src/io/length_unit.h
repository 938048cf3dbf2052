// The unit of a file's lengths (spacing, origin) in one spelling, whatever the format wrote.
#pragma once

#include <string>

namespace ewa {

// "mm", "µm", "nm", "cm", "m", "pm" or "Å" for the usual spellings of each ("millimeter",
// "micron", "um", "\u00B5m", "angstrom", ...), any other short printable name as written, and ""
// for an empty, long or unprintable one (a file's text is not trusted to be a unit).
std::string lengthUnitName(const std::string& text);

}  // namespace ewa

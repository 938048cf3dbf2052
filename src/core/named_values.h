// Names of enum values for the command line, the settings file and the statistics: one table
// per enum gives both directions, so a name and its parse cannot drift apart.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ewa {

template <typename E>
struct NamedValue {
  E value;
  const char* name;
};

// The name of `value` in `table`; "?" for a value the table lacks (a cast out of range).
template <typename E, size_t N>
const char* nameIn(const NamedValue<E> (&table)[N], E value) {
  for (const NamedValue<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

// Every name in `table`, in order: the values an option accepts, for its check and its help.
template <typename E, size_t N>
std::vector<std::string> namesIn(const NamedValue<E> (&table)[N]) {
  std::vector<std::string> names;
  for (const NamedValue<E>& entry : table) names.emplace_back(entry.name);
  return names;
}

// The value named `text` in `table` into *value; false (and *value untouched) for any other text.
template <typename E, size_t N>
bool parseIn(const NamedValue<E> (&table)[N], const std::string& text, E* value) {
  for (const NamedValue<E>& entry : table)
    if (text == entry.name) {
      *value = entry.value;
      return true;
    }
  return false;
}

}  // namespace ewa

#pragma once
// Lookup in a registry of plug-in types (shapes, contact laws): each entry has a `name`.
#include <string>
#include <vector>

#include "picdem/core/error.hpp"

namespace picdem::core {

/// The entry of `types` called `name`; InputError "<what> '<name>' is not known; allowed: ..."
/// listing the known names otherwise.
template <class T>
const T& find_named(const std::vector<T>& types, const std::string& name, const std::string& what) {
  std::string known;
  for (const auto& t : types) {
    if (t.name == name) return t;
    known += (known.empty() ? "" : ", ") + t.name;
  }
  throw InputError(what + " '" + name + "' is not known; allowed: " + known);
}

}  // namespace picdem::core

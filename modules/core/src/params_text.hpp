#pragma once
// Text and path helpers shared by the parameter files (params*.cpp); private to core.
#include <Teuchos_ParameterList.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace picdem::core::detail {

/// "a/b/c" -> {"a", "b", "c"}.
std::vector<std::string> split_path(const std::string& path);
/// A number with 10 significant digits.
std::string fmt(double v);
std::string join(const std::vector<std::string>& v, const std::string& sep);
/// Levenshtein distance (for "did you mean").
std::size_t edit_distance(const std::string& a, const std::string& b);
/// A short description of what a YAML entry holds, for messages.
std::string describe(const Teuchos::ParameterEntry& e);
void set_path(Teuchos::ParameterList& root, const std::string& path,
              const Teuchos::ParameterEntry& e);
bool has_path(const Teuchos::ParameterList& root, const std::string& path);

}  // namespace picdem::core::detail

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

/// YAML text as Teuchos' reader takes it. That reader refuses two forms YAML allows: a flow list
/// or mapping continued over several lines, and the empty list "key: []". The first is joined
/// into its first line (blank lines after it keep the line count, so the reader's line numbers
/// still point into the file); the second is taken out (its line left blank) and listed in
/// `empty_arrays`, to be put back by put_back_empty_arrays. `skip_levels` sublists at the top
/// (the wrapper Teuchos needs) are not part of the listed paths.
struct ReadableYaml {
  std::string text;
  std::vector<std::pair<std::vector<std::string>, std::string>> empty_arrays;  // sublists, key
};
ReadableYaml readable_yaml(const std::string& yaml, std::size_t skip_levels);
/// Sets each listed key to an empty real array (the only array kind of a case).
void put_back_empty_arrays(Teuchos::ParameterList& root, const ReadableYaml& y);

}  // namespace picdem::core::detail

// Text and path helpers of the parameter files (params_text.hpp).
#include "params_text.hpp"

#include <algorithm>
#include <sstream>

namespace picdem::core::detail {

using Teuchos::ParameterList;

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : path) {
    if (c == '/') {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string describe(const Teuchos::ParameterEntry& e) {
  if (e.isList()) return "a section";
  if (e.isType<std::string>()) return "the text '" + Teuchos::getValue<std::string>(e) + "'";
  if (e.isType<bool>()) return Teuchos::getValue<bool>(e) ? "true" : "false";
  if (e.isType<int>()) return std::to_string(Teuchos::getValue<int>(e));
  if (e.isType<long long>()) return std::to_string(Teuchos::getValue<long long>(e));
  if (e.isType<double>()) return fmt(Teuchos::getValue<double>(e));
  std::ostringstream s;
  s << e.getAny(false);
  return (e.isArray() ? "the list " : "'") + s.str() + (e.isArray() ? "" : "'");
}

void set_path(ParameterList& root, const std::string& path, const Teuchos::ParameterEntry& e) {
  const auto parts = split_path(path);
  ParameterList* pl = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) pl = &pl->sublist(parts[i]);
  pl->setEntry(parts.back(), e);
}

bool has_path(const ParameterList& root, const std::string& path) {
  const auto parts = split_path(path);
  const ParameterList* pl = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (!pl->isSublist(parts[i])) return false;
    pl = &pl->sublist(parts[i]);
  }
  return pl->isParameter(parts.back());
}

}  // namespace picdem::core::detail

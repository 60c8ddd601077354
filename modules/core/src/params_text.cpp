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

namespace {

// Scans `line` outside quotes: adds the flow collections it opens and closes to `depth` and
// returns where its comment ('#' after a blank or at the start) begins, npos without one.
std::size_t scan_line(const std::string& line, int& depth) {
  char quote = 0;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && (k == 0 || line[k - 1] == ' ' || line[k - 1] == '\t')) {
      return k;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::string::npos;
}

void count_brackets(const std::string& line, int& depth) {
  scan_line(line, depth);
}

std::string without_comment(const std::string& line) {
  int depth = 0;
  return line.substr(0, scan_line(line, depth));
}

// YAML lets a block list sit at its key's own indentation ("key:" then "- 1" below it, as PyYAML
// writes lists); Teuchos' reader takes only lists indented deeper than their key. Moves such
// items (and the lines that continue them) two columns right; the line count is unchanged.
void indent_block_sequences(std::vector<std::string>& lines) {
  auto indent_of = [](const std::string& l) { return l.find_first_not_of(' '); };
  auto is_item = [](const std::string& l, std::size_t at) {
    return l.compare(at, 2, "- ") == 0 || (l.size() == at + 1 && l[at] == '-');
  };
  for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
    const std::string key_line = without_comment(lines[k]);
    const auto key_indent = indent_of(key_line);
    const auto last = key_line.find_last_not_of(" \t");
    if (key_indent == std::string::npos || key_line[last] != ':') continue;
    std::size_t n = k + 1;
    while (n < lines.size() && indent_of(without_comment(lines[n])) == std::string::npos) ++n;
    if (n == lines.size() || indent_of(lines[n]) != key_indent || !is_item(lines[n], key_indent))
      continue;
    for (; n < lines.size(); ++n) {
      const auto at = indent_of(without_comment(lines[n]));
      if (at != std::string::npos &&
          (at < key_indent || (at == key_indent && !is_item(lines[n], at))))
        break;
      if (at != std::string::npos) lines[n].insert(0, "  ");
    }
    k = n - 1;
  }
}
}  // namespace

ReadableYaml readable_yaml(const std::string& yaml, std::size_t skip_levels) {
  // Join the continuation lines of open flow collections.
  std::vector<std::string> lines;
  {
    std::istringstream in(yaml);
    std::string joined;
    int depth = 0, pending = 0;
    for (std::string line; std::getline(in, line);) {
      if (depth > 0) {
        const auto first = line.find_first_not_of(" \t");
        joined += " " + without_comment(first == std::string::npos ? "" : line.substr(first));
        ++pending;
      } else {
        joined = line;
      }
      count_brackets(line, depth);
      if (depth > 0) {
        joined = without_comment(joined);
        continue;
      }
      lines.push_back(joined);
      for (; pending > 0; --pending) lines.emplace_back();
    }
    if (depth > 0) lines.push_back(joined);  // unclosed: left for the reader to refuse
  }
  indent_block_sequences(lines);
  // Take out "key: []", remembering its sublists.
  ReadableYaml out;
  std::vector<std::pair<std::size_t, std::string>> open;  // indentation, name of each open sublist
  for (const std::string& line : lines) {
    const auto indent = line.find_first_not_of(' ');
    const auto colon = line.find(": ");
    if (indent != std::string::npos && colon != std::string::npos) {
      while (!open.empty() && open.back().first >= indent) open.pop_back();
      const std::string key = line.substr(indent, colon - indent);
      const std::string value = without_comment(line.substr(colon + 2));
      const auto last = value.find_last_not_of(" \t");
      if (last != std::string::npos && value.substr(0, last + 1) == "[]") {
        std::vector<std::string> path;
        for (std::size_t n = skip_levels; n < open.size(); ++n) path.push_back(open[n].second);
        out.empty_arrays.emplace_back(path, key);
        out.text += "\n";
        continue;
      }
      if (last == std::string::npos) open.emplace_back(indent, key);
    } else if (indent != std::string::npos && line.back() == ':') {
      while (!open.empty() && open.back().first >= indent) open.pop_back();
      open.emplace_back(indent, line.substr(indent, line.size() - 1 - indent));
    }
    out.text += line + "\n";
  }
  return out;
}

void put_back_empty_arrays(Teuchos::ParameterList& root, const ReadableYaml& y) {
  for (const auto& [path, key] : y.empty_arrays) {
    Teuchos::ParameterList* list = &root;
    for (const auto& name : path) list = &list->sublist(name);
    list->set(key, Teuchos::Array<double>());
  }
}

}  // namespace picdem::core::detail

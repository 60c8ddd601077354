// The values of a validated case (Params) and reading case files: YAML, --set overrides, the
// case on every rank. Declarations: params_schema.cpp; validation: params_resolve.cpp.
#include "picdem/core/params.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "params_text.hpp"
#include "picdem/core/error.hpp"

namespace picdem::core {
namespace {

using Teuchos::ParameterList;

// Rewrites Teuchos' "line N column M" (of the wrapped text) into the user's coordinates.
std::string yaml_error_message(const std::string& what, const std::string& source) {
  std::smatch m;
  static const std::regex where("line ([0-9]+) column ([0-9]+)");
  std::string first_lines;
  {
    std::istringstream in(what);
    std::string line;
    int n = 0;
    while (std::getline(in, line) && n < 3) {
      if (line.find("Throw") != std::string::npos || line.find(".cpp:") != std::string::npos)
        continue;
      if (line.empty()) continue;
      first_lines += (n ? " | " : "") + line;
      ++n;
    }
  }
  if (std::regex_search(what, m, where)) {
    const int line = std::stoi(m[1]) - 1;
    const int col = std::max(1, std::stoi(m[2]) - 2);
    return source + ": not valid YAML at line " + std::to_string(line) + ", column " +
           std::to_string(col) + " (picdem case files are YAML mappings of sections and keys)";
  }
  return source + ": not valid YAML (" + first_lines + ")";
}

}  // namespace

using detail::set_path;
using detail::split_path;
using Teuchos::ParameterList;

// ---------------------------------------------------------------------------------------------
// Params

Params::Params() : list_(std::make_shared<ParameterList>("case")) {}
Params::Params(std::shared_ptr<const ParameterList> list, std::string prefix)
    : list_(std::move(list)), prefix_(std::move(prefix)) {}

const ParameterList& Params::node(const std::string& path, std::string* leaf) const {
  const auto parts = split_path(path);
  const ParameterList* pl = list_.get();
  const std::size_t n = leaf ? parts.size() - 1 : parts.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (parts[i].empty()) continue;
    if (!pl->isSublist(parts[i]))
      throw std::logic_error("parameter section not declared: " + full_path(path));
    pl = &pl->sublist(parts[i]);
  }
  if (leaf) *leaf = parts.back();
  return *pl;
}

bool Params::has(const std::string& path) const {
  const auto parts = split_path(path);
  const ParameterList* pl = list_.get();
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (!pl->isSublist(parts[i])) return false;
    pl = &pl->sublist(parts[i]);
  }
  return pl->isParameter(parts.back());
}

long long Params::integer(const std::string& path) const {
  std::string leaf;
  const auto& pl = node(path, &leaf);
  if (!pl.isType<int>(leaf)) throw std::logic_error("not an integer parameter: " + full_path(path));
  return pl.get<int>(leaf);
}
double Params::real(const std::string& path) const {
  std::string leaf;
  const auto& pl = node(path, &leaf);
  if (!pl.isType<double>(leaf)) throw std::logic_error("not a real parameter: " + full_path(path));
  return pl.get<double>(leaf);
}
bool Params::boolean(const std::string& path) const {
  std::string leaf;
  const auto& pl = node(path, &leaf);
  if (!pl.isType<bool>(leaf)) throw std::logic_error("not a boolean parameter: " + full_path(path));
  return pl.get<bool>(leaf);
}
std::string Params::string(const std::string& path) const {
  std::string leaf;
  const auto& pl = node(path, &leaf);
  if (!pl.isType<std::string>(leaf))
    throw std::logic_error("not a string parameter: " + full_path(path));
  return pl.get<std::string>(leaf);
}
std::vector<double> Params::reals(const std::string& path) const {
  std::string leaf;
  const auto& pl = node(path, &leaf);
  if (!pl.isType<Teuchos::Array<double>>(leaf))
    throw std::logic_error("not a real-array parameter: " + full_path(path));
  const auto& a = pl.get<Teuchos::Array<double>>(leaf);
  return {a.begin(), a.end()};
}
Params Params::sub(const std::string& path) const {
  const auto& pl = node(path, nullptr);
  auto copy = std::make_shared<ParameterList>(pl);
  return Params(copy, full_path(path) + "/");
}
std::vector<std::string> Params::sublist_names(const std::string& path) const {
  const auto& pl = node(path, nullptr);
  std::vector<std::string> names;
  for (auto it = pl.begin(); it != pl.end(); ++it)
    if (pl.entry(it).isList()) names.push_back(pl.name(it));
  return names;
}
const ParameterList& Params::teuchos(const std::string& path) const {
  return path.empty() ? *list_ : node(path, nullptr);
}
std::string Params::full_path(const std::string& path) const {
  return prefix_ + path;
}
std::string Params::to_yaml() const {
  std::ostringstream s;
  s.setf(std::ios::showpoint);  // Teuchos asks for it so that 1.0 stays a real
  s.precision(17);
  Teuchos::writeParameterListToYamlOStream(*list_, s);
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Reading

namespace {
// Teuchos' reading of YAML text whose one top-level key names the list, with the forms its reader
// refuses (multi-line flow collections, empty lists) handled first (detail::readable_yaml).
Teuchos::RCP<ParameterList> read_yaml(const std::string& text, const std::string& source) {
  const detail::ReadableYaml readable = detail::readable_yaml(text, 1);
  Teuchos::RCP<ParameterList> pl;
  try {
    pl = Teuchos::getParametersFromYamlString(readable.text);
  } catch (const std::exception& e) {
    throw InputError(yaml_error_message(e.what(), source));
  }
  detail::put_back_empty_arrays(*pl, readable);
  return pl;
}
}  // namespace

std::shared_ptr<ParameterList> parse_yaml(const std::string& text, const std::string& source) {
  // Teuchos wants exactly one top-level key naming the list: wrap the user's mapping.
  bool has_content = false;
  std::string wrapped = "case:\n";
  {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const auto first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] != '#') has_content = true;
      wrapped += "  " + line + "\n";
    }
  }
  if (!has_content) throw InputError(source + ": the file holds no parameters (empty case file)");
  if (text.find('\0') != std::string::npos)
    throw InputError(source + ": not a text file (holds NUL bytes); a case file is YAML");
  return std::make_shared<ParameterList>(*read_yaml(wrapped, source));
}

void apply_override(ParameterList& list, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == assignment.size())
    throw InputError("--set '" + assignment + "': expected KEY=VALUE, e.g. --set grid/nx=200");
  const std::string path = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  std::shared_ptr<ParameterList> parsed;
  try {
    parsed = parse_yaml("value: " + value + "\n", "--set " + path);
  } catch (const InputError&) {
    throw InputError("--set '" + assignment + "': the value is not a YAML scalar or list");
  }
  set_path(list, path, parsed->getEntry("value"));
}

Params read_case_text(const std::string& text, const std::string& source,
                      const std::vector<std::string>& overrides, const ParamSchema& schema,
                      const std::string& case_dir) {
  auto list = parse_yaml(text, source);
  ParamSchema::FileBase files{case_dir, {}};
  for (const auto& o : overrides) {
    apply_override(*list, o);
    files.overridden.push_back(o.substr(0, o.find('=')));
  }
  return schema.resolve(*list, overrides.empty() ? source : source + " (with --set overrides)",
                        files);
}

Params resolve_written_case(const std::string& yaml, const std::string& source,
                            const ParamSchema& schema) {
  return schema.resolve(*read_yaml(yaml, source), source);  // "key: []" as Teuchos writes it
}

std::string case_file_path(const Comm& comm, const std::string& path) {
  std::string file = path, problem;
  if (comm.is_root()) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
      file = (std::filesystem::path(path) / "case.yaml").string();
      if (!std::filesystem::is_regular_file(file, ec))
        problem = path +
                  ": a directory, not a case file, and it holds no case.yaml; give the "
                  "case file (e.g. cases/dam_break/case.yaml) or a directory holding "
                  "case.yaml";
    }
  }
  problem = comm.broadcast(problem);
  if (!problem.empty()) throw InputError(problem);
  return comm.broadcast(file);
}

Params read_case(const Comm& comm, const std::string& path,
                 const std::vector<std::string>& overrides, const ParamSchema& schema) {
  const std::string file = case_file_path(comm, path);
  std::string text, problem;
  if (comm.is_root()) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      problem = file + ": cannot open the case file";
    } else {
      std::ostringstream s;
      s << in.rdbuf();
      text = s.str();
    }
  }
  problem = comm.broadcast(problem);
  if (!problem.empty()) throw InputError(problem);
  text = comm.broadcast(text);
  // Relative file paths in the case are the case file's folder's (on every rank the same text).
  const std::string case_dir = comm.broadcast(
      comm.is_root() ? std::filesystem::absolute(file).parent_path().string() : std::string());
  return read_case_text(text, file, overrides, schema, case_dir);
}

}  // namespace picdem::core

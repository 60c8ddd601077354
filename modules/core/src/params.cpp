#include "picdem/core/params.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

#include "picdem/core/error.hpp"

namespace picdem::core {
namespace {

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

/// A short description of what a YAML entry holds, for messages.
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

// ---------------------------------------------------------------------------------------------
// ParamDecl

std::string ParamDecl::kind_name() const {
  switch (kind) {
    case ParamKind::Integer:
      return "integer";
    case ParamKind::Real:
      return "real";
    case ParamKind::Boolean:
      return "boolean";
    case ParamKind::String:
      return "string";
    case ParamKind::RealArray:
      return "list of reals";
    case ParamKind::Passthrough:
      return "section";
  }
  return "?";
}

std::string ParamDecl::allowed() const {
  if (kind == ParamKind::String && !choices.empty()) return "one of: " + join(choices, ", ");
  if (kind == ParamKind::Boolean) return "true or false";
  if (kind == ParamKind::Passthrough) return "any keys (passed to Trilinos unchanged)";
  std::string out;
  if (lo && hi) {
    out = std::string(lo_open ? "(" : "[") + fmt(*lo) + ", " + fmt(*hi) + (hi_open ? ")" : "]");
    out = "in " + out;
  } else if (lo) {
    out = std::string(lo_open ? "> " : ">= ") + fmt(*lo);
  } else if (hi) {
    out = std::string(hi_open ? "< " : "<= ") + fmt(*hi);
  } else {
    out = "any";
  }
  if (kind == ParamKind::RealArray) {
    std::string n;
    if (min_size == max_size)
      n = std::to_string(min_size) + " values";
    else if (max_size >= (1 << 30))
      n = "at least " + std::to_string(min_size) + " values";
    else
      n = std::to_string(min_size) + " to " + std::to_string(max_size) + " values";
    out = n + ", each " + out;
  }
  return out;
}

std::string ParamDecl::default_text() const {
  if (required) return "required";
  switch (kind) {
    case ParamKind::Integer:
      return std::to_string(int_default);
    case ParamKind::Real:
      return fmt(real_default);
    case ParamKind::Boolean:
      return bool_default ? "true" : "false";
    case ParamKind::String:
      return string_default.empty() ? "\"\"" : string_default;
    case ParamKind::RealArray: {
      std::vector<std::string> v;
      for (double d : array_default) v.push_back(fmt(d));
      return "[" + join(v, ", ") + "]";
    }
    case ParamKind::Passthrough:
      return "see text";
  }
  return "";
}

ParamSchema& FamilyDecl::variant(const std::string& type_name, const std::string& variant_doc) {
  auto& s = variants[type_name];
  if (!s) s = std::make_shared<ParamSchema>();
  variant_docs[type_name] = variant_doc;
  return *s;
}

// ---------------------------------------------------------------------------------------------
// ParamSchema declarations

ParamDecl& ParamSchema::add(ParamDecl d) {
  for (const auto& e : decls_)
    if (e.path == d.path) throw std::logic_error("parameter declared twice: " + d.path);
  decls_.push_back(std::move(d));
  return decls_.back();
}

ParamDecl& ParamSchema::integer(const std::string& path, long long def, const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::Integer, d.int_default = def, d.doc = doc;
  return add(d);
}
ParamDecl& ParamSchema::real(const std::string& path, double def, const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::Real, d.real_default = def, d.doc = doc;
  return add(d);
}
ParamDecl& ParamSchema::boolean(const std::string& path, bool def, const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::Boolean, d.bool_default = def, d.doc = doc;
  return add(d);
}
ParamDecl& ParamSchema::string(const std::string& path, const std::string& def,
                               const std::vector<std::string>& choices, const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::String, d.string_default = def, d.choices = choices;
  d.doc = doc;
  return add(d);
}
ParamDecl& ParamSchema::reals(const std::string& path, const std::vector<double>& def,
                              const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::RealArray, d.array_default = def, d.doc = doc;
  return add(d);
}
ParamDecl& ParamSchema::passthrough(const std::string& path, const std::string& def_yaml,
                                    const std::string& doc) {
  ParamDecl d;
  d.path = path, d.kind = ParamKind::Passthrough, d.string_default = def_yaml, d.doc = doc;
  return add(d);
}
FamilyDecl& ParamSchema::family(const std::string& path, const std::string& doc) {
  FamilyDecl f;
  f.path = path, f.doc = doc;
  families_.push_back(std::move(f));
  return families_.back();
}
void ParamSchema::section(const std::string& path, const std::string& doc) {
  sections_.emplace_back(path, doc);
}
void ParamSchema::check(ParamCheck c) {
  checks_.push_back(std::move(c));
}

// ---------------------------------------------------------------------------------------------
// Validation

struct SchemaResolver {
  const ParamSchema& schema;
  std::string prefix;  // path of this schema inside the case ("" or "obstacles/pipe/")
  std::vector<std::string>& errors;

  const ParamDecl* decl(const std::string& path) const {
    for (const auto& d : schema.decls_)
      if (d.path == path) return &d;
    return nullptr;
  }
  const FamilyDecl* family(const std::string& path) const {
    for (const auto& f : schema.families_)
      if (f.path == path) return &f;
    return nullptr;
  }
  bool is_section(const std::string& path) const {
    const std::string p = path + "/";
    for (const auto& d : schema.decls_)
      if (d.path.compare(0, p.size(), p) == 0) return true;
    for (const auto& f : schema.families_)
      if (f.path.compare(0, p.size(), p) == 0) return true;
    for (const auto& s : schema.sections_)
      if (s.first == path) return true;
    return false;
  }
  // Names allowed directly under `rel` ("" or "fluid/").
  std::vector<std::string> children(const std::string& rel) const {
    std::set<std::string> names;
    auto take = [&](const std::string& p) {
      if (p.compare(0, rel.size(), rel) != 0 || p.size() == rel.size()) return;
      const std::string rest = p.substr(rel.size());
      names.insert(rest.substr(0, rest.find('/')));
    };
    for (const auto& d : schema.decls_) take(d.path);
    for (const auto& f : schema.families_) take(f.path);
    for (const auto& s : schema.sections_) take(s.first);
    return {names.begin(), names.end()};
  }

  void unknown(const std::string& rel, const std::string& name) {
    const auto allowed = children(rel);
    std::string best;
    std::size_t best_d = 3;
    for (const auto& a : allowed) {
      const std::size_t d = edit_distance(a, name);
      if (d < best_d) best_d = d, best = a;
    }
    std::string msg = "unknown key '" + prefix + rel + name + "'";
    if (!best.empty()) msg += " (did you mean '" + prefix + rel + best + "'?)";
    const std::string where =
        rel.empty() ? (prefix.empty() ? "at the top level"
                                      : "in '" + prefix.substr(0, prefix.size() - 1) + "'")
                    : "in '" + prefix + rel.substr(0, rel.size() - 1) + "'";
    msg += "; allowed " + where + ": " + join(allowed, ", ");
    errors.push_back(msg);
  }

  bool in_range(const ParamDecl& d, double v) const {
    if (!std::isfinite(v)) return false;
    if (d.lo && (d.lo_open ? !(v > *d.lo) : !(v >= *d.lo))) return false;
    if (d.hi && (d.hi_open ? !(v < *d.hi) : !(v <= *d.hi))) return false;
    return true;
  }

  void value(const ParamDecl& d, const Teuchos::ParameterEntry& e, ParameterList& out,
             const std::string& name) {
    const std::string key = "'" + prefix + d.path + "'";
    auto bad_type = [&] {
      errors.push_back("key " + key + " expects " +
                       (d.kind == ParamKind::Integer   ? std::string("an integer")
                        : d.kind == ParamKind::Real    ? std::string("a real number")
                        : d.kind == ParamKind::Boolean ? std::string("true or false")
                        : d.kind == ParamKind::String
                            ? std::string("a text")
                            : std::string("a list of reals like [1.0, 2.0]")) +
                       ", got " + describe(e));
    };
    auto out_of_range = [&](const std::string& got) {
      errors.push_back("key " + key + " = " + got + " is not allowed: must be " + d.allowed());
    };
    if (e.isList()) {
      errors.push_back("key " + key + " is a single " + d.kind_name() + ", not a section");
      return;
    }
    switch (d.kind) {
      case ParamKind::Integer: {
        long long v;
        if (e.isType<int>())
          v = Teuchos::getValue<int>(e);
        else if (e.isType<long long>())
          v = Teuchos::getValue<long long>(e);
        else
          return bad_type();
        if (!in_range(d, static_cast<double>(v)) || v > std::numeric_limits<int>::max() ||
            v < std::numeric_limits<int>::min())
          return out_of_range(std::to_string(v));
        out.set(name, static_cast<int>(v));
        return;
      }
      case ParamKind::Real: {
        double v;
        if (e.isType<double>())
          v = Teuchos::getValue<double>(e);
        else if (e.isType<int>())
          v = Teuchos::getValue<int>(e);
        else if (e.isType<long long>())
          v = static_cast<double>(Teuchos::getValue<long long>(e));
        else
          return bad_type();
        if (!in_range(d, v)) return out_of_range(fmt(v));
        out.set(name, v);
        return;
      }
      case ParamKind::Boolean:
        if (!e.isType<bool>()) return bad_type();
        out.set(name, Teuchos::getValue<bool>(e));
        return;
      case ParamKind::String: {
        if (!e.isType<std::string>()) return bad_type();
        const auto v = Teuchos::getValue<std::string>(e);
        if (!d.choices.empty() &&
            std::find(d.choices.begin(), d.choices.end(), v) == d.choices.end())
          return out_of_range("'" + v + "'");
        out.set(name, v);
        return;
      }
      case ParamKind::RealArray: {
        Teuchos::Array<double> v;
        if (e.isType<Teuchos::Array<double>>())
          v = Teuchos::getValue<Teuchos::Array<double>>(e);
        else if (e.isType<Teuchos::Array<int>>())
          for (int x : Teuchos::getValue<Teuchos::Array<int>>(e)) v.push_back(x);
        else
          return bad_type();
        if (static_cast<int>(v.size()) < d.min_size || static_cast<int>(v.size()) > d.max_size) {
          errors.push_back("key " + key + " has " + std::to_string(v.size()) +
                           " values; allowed: " + d.allowed());
          return;
        }
        for (double x : v)
          if (!in_range(d, x)) return out_of_range("a list holding " + fmt(x));
        out.set(name, v);
        return;
      }
      case ParamKind::Passthrough:
        return;
    }
  }

  void walk(const ParameterList& in, ParameterList& out, const std::string& rel) {
    for (auto it = in.begin(); it != in.end(); ++it) {
      const std::string& name = in.name(it);
      const auto& e = in.entry(it);
      const std::string path = rel + name;
      if (const ParamDecl* d = decl(path)) {
        if (d->kind == ParamKind::Passthrough) {
          if (!e.isList()) {
            errors.push_back("key '" + prefix + path +
                             "' must be a section of solver settings, got " + describe(e));
            continue;
          }
          // Declared defaults first, then the user's keys on top, otherwise unchanged.
          ParameterList merged = *parse_yaml(d->string_default, "default of " + path);
          merged.setParameters(Teuchos::getValue<ParameterList>(e));
          out.set(name, merged);
        } else {
          value(*d, e, out, name);
        }
      } else if (const FamilyDecl* f = family(path)) {
        if (!e.isList()) {
          errors.push_back("key '" + prefix + path + "' must be a section of named entries, got " +
                           describe(e));
          continue;
        }
        const auto& members = Teuchos::getValue<ParameterList>(e);
        ParameterList& fam_out = out.sublist(name);
        for (auto m = members.begin(); m != members.end(); ++m) {
          const std::string& mname = members.name(m);
          const std::string mpath = prefix + path + "/" + mname;
          std::vector<std::string> types;
          for (const auto& v : f->variants) types.push_back(v.first);
          if (!members.entry(m).isList()) {
            errors.push_back("'" + mpath + "' must be a section with a 'type' key (one of: " +
                             join(types, ", ") + ")");
            continue;
          }
          const auto& member = Teuchos::getValue<ParameterList>(members.entry(m));
          if (!member.isType<std::string>("type")) {
            errors.push_back("'" + mpath + "' needs a key 'type' (one of: " + join(types, ", ") +
                             ")");
            continue;
          }
          const std::string type = member.get<std::string>("type");
          auto v = f->variants.find(type);
          if (v == f->variants.end()) {
            errors.push_back("key '" + mpath + "/type' = '" + type +
                             "' is not allowed: must be one of: " + join(types, ", "));
            continue;
          }
          ParameterList stripped(member);
          stripped.remove("type");
          SchemaResolver sub{*v->second, mpath + "/", errors};
          ParameterList& mout = fam_out.sublist(mname);
          mout.set("type", type);
          sub.walk(stripped, mout, "");
          sub.fill_defaults(stripped, mout);
        }
      } else if (is_section(path)) {
        if (!e.isList()) {
          errors.push_back("key '" + prefix + path + "' is a section (keys: " +
                           join(children(path + "/"), ", ") + "), got " + describe(e));
          continue;
        }
        walk(Teuchos::getValue<ParameterList>(e), out.sublist(name), path + "/");
      } else {
        unknown(rel, name);
      }
    }
  }

  // Completes `out` with defaults for keys absent from `in` (keys present but invalid were
  // already reported by walk()).
  void fill_defaults(const ParameterList& in, ParameterList& out) {
    for (const auto& d : schema.decls_) {
      if (has_path(out, d.path) || has_path(in, d.path)) continue;
      if (d.required) {
        errors.push_back("missing required key '" + prefix + d.path + "' (" + d.kind_name() + ", " +
                         d.allowed() + "): " + d.doc);
        continue;
      }
      Teuchos::ParameterEntry e;
      switch (d.kind) {
        case ParamKind::Integer:
          e.setValue(static_cast<int>(d.int_default));
          break;
        case ParamKind::Real:
          e.setValue(d.real_default);
          break;
        case ParamKind::Boolean:
          e.setValue(d.bool_default);
          break;
        case ParamKind::String:
          e.setValue(d.string_default);
          break;
        case ParamKind::RealArray:
          e.setValue(Teuchos::Array<double>(d.array_default.begin(), d.array_default.end()));
          break;
        case ParamKind::Passthrough:
          e.setValue(*parse_yaml(d.string_default, "default of " + d.path));
          break;
      }
      set_path(out, d.path, e);
    }
    for (const auto& f : schema.families_) {
      const auto parts = split_path(f.path);
      ParameterList* pl = &out;
      for (const auto& p : parts) pl = &pl->sublist(p);
    }
  }
};

Params ParamSchema::resolve(const ParameterList& input, const std::string& source) const {
  std::vector<std::string> errors;
  auto out = std::make_shared<ParameterList>("case");
  SchemaResolver r{*this, "", errors};
  r.walk(input, *out, "");
  r.fill_defaults(input, *out);
  Params params(out);
  if (errors.empty())
    for (const auto& c : checks_) c(params, errors);
  if (!errors.empty()) {
    std::string msg = source + ": ";
    if (errors.size() == 1) {
      msg += errors.front();
    } else {
      msg += std::to_string(errors.size()) + " problems:";
      for (const auto& e : errors) msg += "\n  - " + e;
    }
    throw InputError(msg);
  }
  return params;
}

// ---------------------------------------------------------------------------------------------
// Reference

std::string ParamSchema::reference_markdown() const {
  std::ostringstream out;
  auto table = [&](const std::vector<ParamDecl>& decls, const std::string& section,
                   const std::string& key_prefix) {
    out << "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
    for (const auto& d : decls) {
      const auto parts = split_path(d.path);
      if (!section.empty() && parts.front() != section) continue;
      if (section.empty() && parts.size() > 1) continue;
      out << "| `" << key_prefix << d.path << "` | " << d.kind_name() << " | " << d.default_text()
          << " | " << d.allowed() << " | " << d.doc << " |\n";
    }
    out << "\n";
  };
  std::vector<std::string> order;
  for (const auto& d : decls_) {
    const auto s = split_path(d.path).front();
    if (split_path(d.path).size() > 1 && std::find(order.begin(), order.end(), s) == order.end())
      order.push_back(s);
  }
  for (const auto& f : families_) {
    const auto s = split_path(f.path).front();
    if (std::find(order.begin(), order.end(), s) == order.end()) order.push_back(s);
  }
  bool top = false;
  for (const auto& d : decls_) top |= split_path(d.path).size() == 1;
  if (top) {
    out << "## Top-level keys\n\n";
    table(decls_, "", "");
  }
  for (const auto& s : order) {
    out << "## `" << s << "`\n\n";
    for (const auto& sec : sections_)
      if (sec.first == s) out << sec.second << "\n\n";
    bool any = false;
    for (const auto& d : decls_)
      any |= split_path(d.path).front() == s && split_path(d.path).size() > 1;
    if (any) table(decls_, s, "");
    for (const auto& d : decls_)
      if (d.kind == ParamKind::Passthrough && split_path(d.path).front() == s)
        out << "Default of `" << d.path << "`:\n\n```yaml\n" << d.string_default << "```\n\n";
    for (const auto& f : families_) {
      if (split_path(f.path).front() != s) continue;
      out << "`" << f.path << "` holds any number of named entries. " << f.doc
          << " Each entry has a key `type`:\n\n";
      for (const auto& v : f.variants) {
        out << "### `" << f.path << "/<name>` with `type: " << v.first << "`\n\n"
            << f.variant_docs.at(v.first) << "\n\n";
        if (!v.second->decls_.empty()) table(v.second->decls_, "", "");
      }
    }
  }
  return out.str();
}

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
  Teuchos::RCP<ParameterList> pl;
  try {
    pl = Teuchos::getParametersFromYamlString(wrapped);
  } catch (const std::exception& e) {
    throw InputError(yaml_error_message(e.what(), source));
  }
  return std::make_shared<ParameterList>(*pl);
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
                      const std::vector<std::string>& overrides, const ParamSchema& schema) {
  auto list = parse_yaml(text, source);
  for (const auto& o : overrides) apply_override(*list, o);
  return schema.resolve(*list, overrides.empty() ? source : source + " (with --set overrides)");
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
  return read_case_text(text, file, overrides, schema);
}

}  // namespace picdem::core

// The parameter schema's declarations (ParamDecl, FamilyDecl, ParamSchema's declaring verbs)
// and the reference it prints (doc/parameters.md). Validation: params_resolve.cpp.
#include <algorithm>
#include <sstream>

#include "params_text.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/params.hpp"

namespace picdem::core {

using detail::fmt;
using detail::join;
using detail::split_path;

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

}  // namespace picdem::core

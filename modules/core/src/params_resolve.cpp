// Validation of a case against the schema: unknown keys with suggestions, kinds, ranges, allowed
// values, families, defaults filled in, the checks across keys (ParamSchema::resolve).
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "params_text.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/params.hpp"

namespace picdem::core {

using detail::describe;
using detail::edit_distance;
using detail::fmt;
using detail::has_path;
using detail::join;
using detail::set_path;
using detail::split_path;
using Teuchos::ParameterList;

// ---------------------------------------------------------------------------------------------
// Validation

struct SchemaResolver {
  const ParamSchema& schema;
  std::string prefix;  // path of this schema inside the case ("" or "obstacles/pipe/")
  std::vector<std::string>& errors;
  const ParamSchema::FileBase& files;

  // A file key's value made absolute (ParamSchema::FileBase); as written without a case folder.
  std::string file_value(const std::string& full_path, const std::string& v) const {
    namespace fs = std::filesystem;
    if (files.case_dir.empty() || v.empty() || fs::path(v).is_absolute()) return v;
    const bool from_command_line = std::find(files.overridden.begin(), files.overridden.end(),
                                             full_path) != files.overridden.end();
    const fs::path base = from_command_line ? fs::current_path() : fs::path(files.case_dir);
    return (base / v).lexically_normal().string();
  }

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

  // The entry's value when it holds what YAML gives for the kind (an integer; a real or an
  // integer; a list of reals or of integers), else nullopt.
  static std::optional<long long> integer_of(const Teuchos::ParameterEntry& e) {
    if (e.isType<int>()) return Teuchos::getValue<int>(e);
    if (e.isType<long long>()) return Teuchos::getValue<long long>(e);
    return std::nullopt;
  }
  static std::optional<double> real_of(const Teuchos::ParameterEntry& e) {
    if (e.isType<double>()) return Teuchos::getValue<double>(e);
    if (e.isType<int>()) return Teuchos::getValue<int>(e);
    if (e.isType<long long>()) return static_cast<double>(Teuchos::getValue<long long>(e));
    return std::nullopt;
  }
  static std::optional<Teuchos::Array<double>> reals_of(const Teuchos::ParameterEntry& e) {
    if (e.isType<Teuchos::Array<double>>()) return Teuchos::getValue<Teuchos::Array<double>>(e);
    if (!e.isType<Teuchos::Array<int>>()) return std::nullopt;
    Teuchos::Array<double> v;
    for (int x : Teuchos::getValue<Teuchos::Array<int>>(e)) v.push_back(x);
    return v;
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
        const auto v = integer_of(e);
        if (!v) return bad_type();
        if (!in_range(d, static_cast<double>(*v)) || *v > std::numeric_limits<int>::max() ||
            *v < std::numeric_limits<int>::min())
          return out_of_range(std::to_string(*v));
        out.set(name, static_cast<int>(*v));
        return;
      }
      case ParamKind::Real: {
        const auto v = real_of(e);
        if (!v) return bad_type();
        if (!in_range(d, *v)) return out_of_range(fmt(*v));
        out.set(name, *v);
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
        out.set(name, d.file_path ? file_value(prefix + d.path, v) : v);
        return;
      }
      case ParamKind::RealArray: {
        const auto v = reals_of(e);
        if (!v) return bad_type();
        if (static_cast<int>(v->size()) < d.min_size || static_cast<int>(v->size()) > d.max_size) {
          errors.push_back("key " + key + " has " + std::to_string(v->size()) +
                           " values; allowed: " + d.allowed());
          return;
        }
        for (double x : *v)
          if (!in_range(d, x)) return out_of_range("a list holding " + fmt(x));
        out.set(name, *v);
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
          SchemaResolver sub{*v->second, mpath + "/", errors, files};
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

Params ParamSchema::resolve(const ParameterList& input, const std::string& source,
                            const FileBase& files) const {
  std::vector<std::string> errors;
  auto out = std::make_shared<ParameterList>("case");
  SchemaResolver r{*this, "", errors, files};
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

}  // namespace picdem::core

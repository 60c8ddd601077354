#pragma once
// Case-file parameters. Every parameter is declared once, by the module that uses it, with its
// type, default, allowed values and a one-line doc. A case file (YAML read by Teuchos) is
// validated against the declarations on every rank before anything runs: unknown keys, wrong
// types and values out of range are errors that name the key, the value and what is allowed.
// The case-file reference in doc/ is generated from the same declarations.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "picdem/core/comm.hpp"

namespace Teuchos {
class ParameterList;
}

namespace picdem::core {

enum class ParamKind { Integer, Real, Boolean, String, RealArray, Passthrough };

/// One declared parameter. Built through ParamSchema, refined by the chained setters.
struct ParamDecl {
  std::string path;  ///< "section/key", relative to the schema that holds it
  ParamKind kind = ParamKind::Real;
  std::string doc;
  bool required = false;
  long long int_default = 0;
  double real_default = 0.0;
  bool bool_default = false;
  std::string string_default;
  std::vector<double> array_default;
  std::optional<double> lo, hi;  ///< bounds on numbers (every element of arrays)
  bool lo_open = false, hi_open = false;
  std::vector<std::string> choices;  ///< allowed strings (empty: any)
  int min_size = 0, max_size = 1 << 30;
  /// A string naming a file: read_case makes a relative path absolute, against the case file's
  /// folder when the case file gives it and against the working directory when --set does.
  bool file_path = false;

  ParamDecl& at_least(double v) { return lo = v, lo_open = false, *this; }
  ParamDecl& greater_than(double v) { return lo = v, lo_open = true, *this; }
  ParamDecl& at_most(double v) { return hi = v, hi_open = false, *this; }
  ParamDecl& less_than(double v) { return hi = v, hi_open = true, *this; }
  ParamDecl& positive() { return greater_than(0.0); }
  ParamDecl& non_negative() { return at_least(0.0); }
  ParamDecl& is_required() { return required = true, *this; }
  ParamDecl& size(int min, int max) { return min_size = min, max_size = max, *this; }
  ParamDecl& is_file_path() { return file_path = true, *this; }

  /// "integer", "real", "real array", ...
  std::string kind_name() const;
  /// Human form of the allowed values: "> 0", "in [0, 1]", "one of: a, b".
  std::string allowed() const;
  /// Human form of the default ("required" when there is none).
  std::string default_text() const;
};

class Params;
class ParamSchema;

/// A family of named sublists of one of several variants chosen by their "type" key, e.g.
///   obstacles: { left_wall: {type: box, ...}, slope: {type: polygon, ...} }
struct FamilyDecl {
  std::string path;
  std::string doc;
  std::map<std::string, std::shared_ptr<ParamSchema>> variants;
  std::map<std::string, std::string> variant_docs;

  /// Declares variant `type_name`; declare its keys on the returned schema.
  ParamSchema& variant(const std::string& type_name, const std::string& variant_doc);
};

/// Cross-parameter check run after validation: append one message per problem.
using ParamCheck = std::function<void(const Params&, std::vector<std::string>& errors)>;

class ParamSchema {
 public:
  ParamDecl& integer(const std::string& path, long long def, const std::string& doc);
  ParamDecl& real(const std::string& path, double def, const std::string& doc);
  ParamDecl& boolean(const std::string& path, bool def, const std::string& doc);
  ParamDecl& string(const std::string& path, const std::string& def,
                    const std::vector<std::string>& choices, const std::string& doc);
  ParamDecl& reals(const std::string& path, const std::vector<double>& def, const std::string& doc);
  /// A sublist handed unchanged to a library (Belos, MueLu); `def` is its default YAML content.
  ParamDecl& passthrough(const std::string& path, const std::string& def_yaml,
                         const std::string& doc);
  FamilyDecl& family(const std::string& path, const std::string& doc);
  /// One-line description of a section ("fluid"), shown in the reference.
  void section(const std::string& path, const std::string& doc);
  void check(ParamCheck c);

  /// Where the relative paths of file keys (ParamDecl::is_file_path) are taken from: `case_dir`
  /// for those the case file gives, the working directory for the keys in `overridden` (given by
  /// --set). An empty case_dir leaves every path as written (a case given as text).
  struct FileBase {
    std::string case_dir;
    std::vector<std::string> overridden;  ///< full key paths ("solids/rock/file")
  };

  /// Validates `input` and returns it completed with defaults. Throws InputError listing every
  /// problem found. `where` prefixes key paths in messages (used for families).
  Params resolve(const Teuchos::ParameterList& input, const std::string& source,
                 const FileBase& files = {}) const;

  /// The case-file reference as Markdown.
  std::string reference_markdown() const;

  const std::vector<ParamDecl>& declarations() const { return decls_; }
  const std::vector<FamilyDecl>& families() const { return families_; }

 private:
  friend struct SchemaResolver;
  ParamDecl& add(ParamDecl d);
  std::vector<ParamDecl> decls_;
  std::vector<FamilyDecl> families_;
  std::vector<std::pair<std::string, std::string>> sections_;
  std::vector<ParamCheck> checks_;
};

/// Validated parameters (read-only view). Paths are "section/key".
class Params {
 public:
  Params();
  explicit Params(std::shared_ptr<const Teuchos::ParameterList> list, std::string prefix = "");

  bool has(const std::string& path) const;
  long long integer(const std::string& path) const;
  double real(const std::string& path) const;
  bool boolean(const std::string& path) const;
  std::string string(const std::string& path) const;
  std::vector<double> reals(const std::string& path) const;
  /// The sublist at `path` as its own view.
  Params sub(const std::string& path) const;
  /// The names of the sublists directly under `path`, in file order.
  std::vector<std::string> sublist_names(const std::string& path) const;
  /// The underlying Teuchos list at `path` (for passthrough sublists).
  const Teuchos::ParameterList& teuchos(const std::string& path = "") const;
  /// The full path of `path` inside the case ("fluid/density").
  std::string full_path(const std::string& path) const;
  /// YAML text of the whole list.
  std::string to_yaml() const;

 private:
  const Teuchos::ParameterList& node(const std::string& path, std::string* leaf) const;
  std::shared_ptr<const Teuchos::ParameterList> list_;
  std::string prefix_;
};

/// Parses YAML text (a plain mapping at top level) into a Teuchos list. Throws InputError whose
/// message cites `source` and the line and column in the user's text.
std::shared_ptr<Teuchos::ParameterList> parse_yaml(const std::string& text,
                                                   const std::string& source);

/// Applies one "--set path=value" override (value parsed as YAML) to `list`.
void apply_override(Teuchos::ParameterList& list, const std::string& assignment);

/// The case file a path names: the path itself, or DIR/case.yaml when the path is a directory
/// holding one (cases/NAME/ as well as cases/NAME/case.yaml). Decided on rank 0 and broadcast;
/// a directory without case.yaml throws InputError (on every rank) saying so.
std::string case_file_path(const Comm& comm, const std::string& path);

/// Reads `file` (or the case.yaml of a directory: case_file_path) on rank 0, broadcasts it, parses
/// it, applies the overrides and validates against `schema` on every rank. Every rank throws the
/// same InputError on bad input.
Params read_case(const Comm& comm, const std::string& file,
                 const std::vector<std::string>& overrides, const ParamSchema& schema);

/// Resolves a case written by Params::to_yaml (a checkpoint's case, possibly of an older picdem)
/// against `schema`: keys declared since then take their defaults.
Params resolve_written_case(const std::string& yaml, const std::string& source,
                            const ParamSchema& schema);

/// Validates YAML text (for tests and tools): parse + overrides + resolve. A non-empty `case_dir`
/// is the folder relative file paths are taken from (read_case: the case file's).
Params read_case_text(const std::string& text, const std::string& source,
                      const std::vector<std::string>& overrides, const ParamSchema& schema,
                      const std::string& case_dir = "");

}  // namespace picdem::core

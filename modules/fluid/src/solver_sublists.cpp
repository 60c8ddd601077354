// MueLu's smoother and coarse-solver sublists checked before the run by the Trilinos objects
// they configure (solver_sublists.hpp). One of the few files that include Ifpack2 and MueLu.
#include "solver_sublists.hpp"

#include <Ifpack2_Factory.hpp>
#include <MueLu_DirectSolver.hpp>
#include <MueLu_MasterList.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <mpi.h>

#include <sstream>
#include <vector>

#include "picdem/core/error.hpp"

namespace picdem::fluid::detail {
namespace {

using Matrix = Tpetra::CrsMatrix<>;
using RowMatrix = Tpetra::RowMatrix<>;
using SC = Matrix::scalar_type;
using LO = Matrix::local_ordinal_type;
using GO = Matrix::global_ordinal_type;
using NO = Matrix::node_type;

// A 4-row 1D Laplacian on this rank alone: Ifpack2 reads its parameters from any matrix.
Teuchos::RCP<const RowMatrix> tiny_matrix() {
  const auto comm = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const auto map = Teuchos::rcp(new Tpetra::Map<>(4, 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 3));
  for (GO i = 0; i < 4; ++i) {
    std::vector<GO> cols;
    std::vector<SC> vals;
    for (GO j = i - 1; j <= i + 1; ++j) {
      if (j < 0 || j > 3) continue;
      cols.push_back(j);
      vals.push_back(j == i ? 2.0 : -1.0);
    }
    A->insertGlobalValues(i, Teuchos::arrayViewFromVector(cols),
                          Teuchos::arrayViewFromVector(vals));
  }
  A->fillComplete();
  return A;
}

// Trilinos' message without its source locations, throw counters and factory pointers.
std::string reason(const std::string& what) {
  std::istringstream in(what);
  std::string line, out;
  int kept = 0;
  while (std::getline(in, line) && kept < 14) {
    if (line.find_first_not_of(" \t") == std::string::npos || line.rfind("Throw", 0) == 0 ||
        line.find(".hpp:") != std::string::npos || line.find(".cpp:") != std::string::npos ||
        line.find("Teuchos::RCP<") != std::string::npos)
      continue;
    if (line.rfind("Belos was disabled", 0) == 0 || line.rfind("Stratimikos was", 0) == 0) break;
    out += (kept++ ? "\n  " : "") + line;
  }
  return out;
}

std::string value_text(const Teuchos::ParameterEntry& e) {
  std::ostringstream s;
  s << e.getAny(false);
  return e.isType<std::string>() ? "'" + s.str() + "'" : s.str();
}

// What a component does with a sublist: throws (with Trilinos' message) if it rejects it; keys
// it did not read are left unused in `list` (Teuchos marks a key used when it is read).
using Apply = void (*)(const std::string& type, Teuchos::ParameterList& list);

void apply_ifpack2(const std::string& type, Teuchos::ParameterList& list) {
  auto prec = Ifpack2::Factory::create<RowMatrix>(type, tiny_matrix());
  prec->setParameters(list);
}

void apply_direct(const std::string& type, Teuchos::ParameterList& list) {
  MueLu::DirectSolver<SC, LO, GO, NO> solver(type, list);
}

// The sublist `name` of `muelu` given to the component of `type`; throws InputError naming the
// first key it rejects (tried alone when the whole list fails), or a key it never reads.
void check_sublist(const std::string& key, const Teuchos::ParameterList& muelu,
                   const std::string& name, const std::string& type, const std::string& who,
                   Apply apply) {
  if (!muelu.isSublist(name)) return;
  const Teuchos::ParameterList& given = muelu.sublist(name);
  const std::string where = key + "/" + name + "/";
  auto fail = [&](const std::string& entry, const std::string& why) {
    throw core::InputError("key '" + where + entry + "' = " + value_text(given.getEntry(entry)) +
                           " is not allowed: " + why);
  };
  Teuchos::ParameterList all = given;
  try {
    apply(type, all);
  } catch (const std::exception& whole) {
    for (auto it = given.begin(); it != given.end(); ++it) {
      Teuchos::ParameterList one;
      one.setEntry(given.name(it), given.entry(it));
      try {
        apply(type, one);
      } catch (const std::exception& e) {
        fail(given.name(it), who + " rejects it: " + reason(e.what()));
      }
    }
    throw core::InputError("key '" + key + "/" + name + "' is not allowed: " + who +
                           " rejects the keys together: " + reason(whole.what()));
  }
  // A component that validates its keys rejects one it does not know (tried above); one that
  // does not would silently ignore a misspelt key: such keys it never read are refused.
  Teuchos::ParameterList probe;
  probe.set("picdem: no such key", 0);
  bool validates = false;
  try {
    apply(type, probe);
  } catch (const std::exception&) {
    validates = true;
  }
  if (validates) return;
  for (auto it = given.begin(); it != given.end(); ++it) {
    const Teuchos::ParameterEntry* e = all.getEntryPtr(given.name(it));  // `all` after reading
    if (e && !e->isUsed() && !e->isList())
      fail(given.name(it), who + " does not read it (it would be ignored); see the keys of " +
                               "Ifpack2's " + type + " in the Ifpack2 user's guide");
  }
}

// Keys of a smoother sublist that MueLu's Ifpack2Smoother reads and removes itself before
// Ifpack2 sees the list (MueLu_Ifpack2Smoother_def.hpp, Trilinos 13.2), with their types.
struct MueLuKey {
  const char* name;
  const char* type;
  bool (*is)(const Teuchos::ParameterEntry&);
};
const MueLuKey kMueLuKeys[] = {
    {"chebyshev: use rowsumabs diagonal scaling", "bool",
     [](const Teuchos::ParameterEntry& e) { return e.isType<bool>(); }},
    {"chebyshev: rowsumabs diagonal replacement tolerance", "real",
     [](const Teuchos::ParameterEntry& e) { return e.isType<double>(); }},
    {"chebyshev: rowsumabs diagonal replacement value", "real",
     [](const Teuchos::ParameterEntry& e) { return e.isType<double>(); }},
    {"smoother: use blockcrsmatrix storage", "bool",
     [](const Teuchos::ParameterEntry& e) { return e.isType<bool>(); }},
    {"smoother: neighborhood type", "string",
     [](const Teuchos::ParameterEntry& e) { return e.isType<std::string>(); }},
    {"pcoarsen: hi basis", "string",
     [](const Teuchos::ParameterEntry& e) { return e.isType<std::string>(); }},
};

// `muelu` with MueLu's own keys (of the right type) taken out of the sublist `name`.
void strip_muelu_keys(const std::string& key, Teuchos::ParameterList& muelu,
                      const std::string& name) {
  if (!muelu.isSublist(name)) return;
  Teuchos::ParameterList& l = muelu.sublist(name);
  for (const auto& k : kMueLuKeys) {
    if (!l.isParameter(k.name)) continue;
    if (!k.is(l.getEntry(k.name)))
      throw core::InputError("key '" + key + "/" + name + "/" + k.name +
                             "' = " + value_text(l.getEntry(k.name)) +
                             " is not allowed: MueLu reads it as a " + k.type);
    l.remove(k.name);
  }
}

void check_lists(const std::string& key, const Teuchos::ParameterList& given) {
  auto type_of = [&](const char* k, const std::string& fallback) {
    return given.isType<std::string>(k) ? given.get<std::string>(k) : fallback;
  };
  // MueLu's defaults: RELAXATION smoothers, a SuperLU coarse solve (KLU2 when it is missing).
  const std::string smoother = type_of("smoother: type", "RELAXATION");
  const std::string pre = type_of("smoother: pre type", smoother);
  const std::string post = type_of("smoother: post type", smoother);
  const std::string coarse = type_of("coarse: type", "SuperLU");
  const bool coarse_ifpack2 = coarse != "none" && Ifpack2::Factory::isSupported<Matrix>(coarse);
  Teuchos::ParameterList muelu = given;
  for (const char* name : {"smoother: params", "smoother: pre params", "smoother: post params"})
    strip_muelu_keys(key, muelu, name);
  if (coarse_ifpack2) strip_muelu_keys(key, muelu, "coarse: params");
  const auto ifpack2 = [](const std::string& t) { return "Ifpack2's " + t + " smoother"; };
  check_sublist(key, muelu, "smoother: params", pre, ifpack2(pre), apply_ifpack2);
  if (post != pre)
    check_sublist(key, muelu, "smoother: params", post, ifpack2(post), apply_ifpack2);
  check_sublist(key, muelu, "smoother: pre params", pre, ifpack2(pre), apply_ifpack2);
  check_sublist(key, muelu, "smoother: post params", post, ifpack2(post), apply_ifpack2);
  if (coarse == "none") return;
  if (coarse_ifpack2)
    check_sublist(key, muelu, "coarse: params", coarse, ifpack2(coarse), apply_ifpack2);
  else
    check_sublist(key, muelu, "coarse: params", coarse,
                  "MueLu's direct coarse solver ('" + coarse + "')", apply_direct);
}

}  // namespace

void check_muelu_sublists(const std::string& key, const Teuchos::ParameterList& given) {
  try {
    check_lists(key, given);
  } catch (const core::InputError& e) {
    if (key.rfind("solver/MueLu_", 0) != 0) throw;  // a list of its own: not a merged one
    throw core::InputError(std::string(e.what()) + "\n(" + key + " stands for solver/MueLu with " +
                           key + " merged over it: the key may come from either)");
  }
}

void check_muelu_list(const std::string& key, const Teuchos::ParameterList& muelu) {
  Teuchos::ParameterList top = muelu;
  std::vector<std::string> levels;  // MueLu's "level N" sublists: not in the master list
  for (auto it = top.begin(); it != top.end(); ++it)
    if (top.name(it).rfind("level ", 0) == 0) levels.push_back(top.name(it));
  for (const auto& l : levels) top.remove(l);
  try {
    top.validateParameters(*MueLu::MasterList::List(), 0);
  } catch (const std::exception& e) {
    throw core::InputError(key + ": MueLu rejected the settings: " + e.what());
  }
  // The smoother is built by Ifpack2 only when the hierarchy is: its name checked now.
  for (const char* k : {"smoother: type", "smoother: pre type", "smoother: post type"})
    if (top.isType<std::string>(k) &&
        !Ifpack2::Factory::isSupported<Matrix>(top.get<std::string>(k)))
      throw core::InputError("key '" + key + "/" + k + "' = '" + top.get<std::string>(k) +
                             "' is not allowed: Ifpack2 provides no such smoother (e.g. "
                             "CHEBYSHEV, RELAXATION, ILUT, RILUK, SCHWARZ)");
  check_muelu_sublists(key, top);
}

}  // namespace picdem::fluid::detail

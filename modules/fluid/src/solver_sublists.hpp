#pragma once
// The keys inside MueLu's smoother and coarse-solver sublists, checked before the run by the
// Trilinos objects they configure (MueLu hands them on only when the first hierarchy is built).
#include <Teuchos_ParameterList.hpp>
#include <string>

namespace picdem::fluid::detail {

/// Checks "smoother: params", "smoother: pre params", "smoother: post params" and
/// "coarse: params" of the MueLu list `muelu` (as handed to MueLu; `key` names it in messages,
/// e.g. solver/MueLu_solids) the way MueLu's ParameterListInterpreter builds them: an Ifpack2
/// smoother (every "smoother" type, and a coarse type MueLu builds as a smoother) is created on a
/// 4-row matrix and given the sublist (Ifpack2 rejects a wrong value or type; a key that it does
/// not read, which Ifpack2 would silently ignore, is rejected here); any other coarse type is
/// MueLu's DirectSolver, constructed with the sublist (it validates the keys). The keys MueLu's
/// Ifpack2Smoother reads and removes itself (chebyshev: use rowsumabs diagonal scaling, ...) are
/// only checked for their type. Throws
/// core::InputError "key 'KEY/SUBLIST/NAME' = VALUE is not allowed: WHY".
void check_muelu_sublists(const std::string& key, const Teuchos::ParameterList& muelu);

/// Checks a whole MueLu list `muelu` as handed to MueLu (`key` names it in messages): its top
/// level against MueLu's master list (the "level N" sublists are not checked), the smoother types
/// against Ifpack2's factory (the smoother is built only when the first hierarchy is), then the
/// smoother and coarse sublists (check_muelu_sublists). Throws core::InputError naming the key.
void check_muelu_list(const std::string& key, const Teuchos::ParameterList& muelu);

}  // namespace picdem::fluid::detail

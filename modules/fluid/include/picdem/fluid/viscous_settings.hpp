#pragma once
// The implicit viscous solve's linear-solver settings: the viscous_solver/ keys of the case file,
// declared once (declare_viscous_solver_parameters) with the defaults below, handed to Belos and
// MueLu unchanged and checked by Trilinos' validators before the run (doc/viscous.md, "Linear
// solver").
#include <memory>

#include "picdem/core/params.hpp"

namespace picdem::fluid {

/// Defaults of viscous_solver/tolerance and viscous_solver/max_iterations.
inline constexpr double kViscousTolerance = 1e-12;
inline constexpr int kViscousMaxIterations = 1000;
/// Defaults of viscous_solver/Belos and viscous_solver/MueLu (YAML; Belos' and MueLu's own
/// defaults but for MueLu's verbosity).
extern const char* const kViscousBelosDefaults;
extern const char* const kViscousMueLuDefaults;

struct ViscousSolverSettings {
  double tolerance = kViscousTolerance;        ///< relative true residual to reach
  int max_iterations = kViscousMaxIterations;  ///< CG iterations per solve
  /// viscous_solver/Belos and viscous_solver/MueLu as the case gives them (merged over their
  /// defaults); null: the declared defaults (kViscousBelosDefaults, kViscousMueLuDefaults).
  std::shared_ptr<const Teuchos::ParameterList> belos, muelu;
};

/// Declares viscous_solver/tolerance, viscous_solver/max_iterations, viscous_solver/Belos and
/// viscous_solver/MueLu (src/viscous_solver.cpp).
void declare_viscous_solver_parameters(core::ParamSchema& schema);

/// Reads the viscous_solver/ keys and checks the two lists with Trilinos' validators (Belos'
/// valid parameters of PseudoBlockCG, MueLu's master list, the smoother names and sublists as for
/// solver/MueLu); throws core::InputError naming the key.
ViscousSolverSettings viscous_solver_settings_from(const core::Params& params);

}  // namespace picdem::fluid

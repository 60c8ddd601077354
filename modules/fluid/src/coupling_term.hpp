#pragma once
// The fluid-solid coupling's part of the pressure operator, as a separate piece that another
// coupling scheme can replace (private to the fluid module). PressureSolver assembles
//   [ -L_E + C ] p = -D + c,
// where the fluid rows (-L_E, D) come from pressure_rows.hpp and C, c from a CouplingTerm; after
// the solve the same term gives the loads on the bodies (its adjoint). The paper's scheme (eqs.
// 5-6) is RigidBodyTerm: C = dt sum_s A_s M_s^-1 A_s^T, c = sum_s A_s V*_s, loads J_s p + F_s.
// To use another scheme, implement CouplingTerm and create it in make_coupling_term().
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "pressure_rows.hpp"

namespace picdem::fluid::detail {

class CouplingTerm {
 public:
  virtual ~CouplingTerm() = default;
  /// Adds the term's matrix contributions and right-hand side to `rows` (the owned fluid cells;
  /// row_of gives the row of each owned fluid cell, -1 elsewhere) and keeps what loads() needs.
  /// Collective.
  virtual void add(const std::vector<SolidCoupling>& couplings, double dt, const CellStates& cells,
                   const grid::GridArray<int>& row_of, const grid::Decomposition& d,
                   RowContributions& rows) = 0;
  /// The loads on the coupled bodies from the solved pressure, from what the last add() used; the
  /// same vector, ordered by id, on every rank. Collective.
  virtual std::vector<core::SolidLoads> loads(const grid::CellField& p,
                                              const grid::Decomposition& d) const = 0;
};

/// Rigid bodies coupled through their cut cells (paper eqs. 5-6): the dense block
/// dt A_s M_s^-1 A_s^T of each solid over its fluid cut cells into the matrix (METHOD.md option
/// (a)), or with rows.low_rank set on entry U = [A_s], W = dt M_s^-1 and only the blocks' diagonal
/// into the matrix (option (b)); b += A_s V*_s, and the loads J_s p + F_s from the same rows.
class RigidBodyTerm final : public CouplingTerm {
 public:
  void add(const std::vector<SolidCoupling>& couplings, double dt, const CellStates& cells,
           const grid::GridArray<int>& row_of, const grid::Decomposition& d,
           RowContributions& rows) override;
  std::vector<core::SolidLoads> loads(const grid::CellField& p,
                                      const grid::Decomposition& d) const override;

 private:
  /// The couplings of the last add(), joined over ranks, with the cells that are not fluid on
  /// their owner left out: the rows a_{s,c} of the matrix.
  std::map<std::int64_t, SolidCoupling> rows_;
};

/// The coupling term the pressure solver uses.
inline std::unique_ptr<CouplingTerm> make_coupling_term() {
  return std::make_unique<RigidBodyTerm>();
}

}  // namespace picdem::fluid::detail

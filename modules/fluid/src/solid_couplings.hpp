#pragma once
// Joining the per-rank SolidCoupling lists (private to the fluid module).
#include <cstdint>
#include <map>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid::detail {

/// Every solid's coupling joined over ranks: partial lists with the same id are concatenated in
/// rank order; the result is the same on every rank. Throws InputError on bad sizes or masses.
std::map<std::int64_t, SolidCoupling> gather_couplings(const std::vector<SolidCoupling>& mine,
                                                       const core::Comm& comm);

/// J_s p + F_s of every joined coupling (eq. 6): -sum_c a_{s,c} p_c over the listed cells that
/// this rank owns (the fluid cells: RigidBodyTerm keeps only those), summed over ranks, plus the
/// joined SolidCoupling::load. The same vector, ordered by id, on every rank.
std::vector<core::SolidLoads> coupling_loads(const std::map<std::int64_t, SolidCoupling>& joined,
                                             const grid::CellField& p,
                                             const grid::Decomposition& d);

}  // namespace picdem::fluid::detail

#pragma once
// Joining the per-rank SolidCoupling lists (private to the fluid module).
#include <cstdint>
#include <map>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/fluid/pressure_solver.hpp"

namespace picdem::fluid::detail {

/// Every solid's coupling joined over ranks: partial lists with the same id are concatenated in
/// rank order; the result is the same on every rank. Throws InputError on bad sizes or masses.
std::map<std::int64_t, SolidCoupling> gather_couplings(const std::vector<SolidCoupling>& mine,
                                                       const core::Comm& comm);

}  // namespace picdem::fluid::detail

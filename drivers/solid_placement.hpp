#pragma once
// Where the case file puts its solids, checked before anything runs (doc/parameters.md, "Checks
// before the run"): every solid inside the tank, no two solids overlapping, no solid overlapping
// an obstacle, no obstacle far outside the tank or wholly outside it, and (with water) no solid
// narrower than a cell. Contact is allowed: real boundaries at zero distance or more pass.
#include <string>
#include <vector>

#include "picdem/core/params.hpp"

namespace picdem::driver {

/// One message per misplaced solid or overlapping pair of the validated case `params`, naming the
/// solids by their case-file entry (solids/NAME, solids/NAME[k] for the k-th shape of a generator)
/// and id, the distance or overlap depth in m and what is allowed. Pairs are found with a grid of
/// buckets (O(N)); at most `max_messages` messages, then one saying how many more there are.
std::vector<std::string> check_solid_placement(const core::Params& params,
                                               std::size_t max_messages = 20);

}  // namespace picdem::driver

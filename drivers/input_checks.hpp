#pragma once
// Checks of a validated case before anything runs (doc/parameters.md, "Checks before the run"): the
// solids' placement (solid_placement.hpp), the linear-solver sublists against Trilinos' own
// validators, and an estimate of the memory each rank needs against its share of the machine.
#include <string>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"

namespace picdem::driver {

/// Memory a rank needs for the grid fields, the pressure system and the particles [bytes]: an
/// estimate from the cell count, the water's area, particles/per_cell_1d and the number of
/// ranks, with the per-cell and per-particle sizes measured on this code (doc/cases.md).
double memory_estimate_bytes(const core::Params& params, int ranks);

/// The memory a rank may use [bytes]: run/memory_limit_gb when set, else MemTotal of
/// /proc/meminfo divided by the ranks on this node; the smallest over all ranks.
double memory_limit_bytes(const core::Comm& comm, const core::Params& params);

/// The description of the checks for the preamble of doc/parameters.md.
std::string checks_markdown();

/// Runs every check; throws core::InputError listing every failure (the same on every rank).
void check_case(const core::Comm& comm, const core::Params& params);

}  // namespace picdem::driver

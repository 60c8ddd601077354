#pragma once
// Loads a shipped case file through the same schema and validation as the executable.
#include <cstdio>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/coupling/schema.hpp"

namespace picdem::test_support {

inline core::Params load_case(const core::Comm& comm, const std::string& relative_path,
                              const std::vector<std::string>& overrides = {}) {
  return core::read_case(comm, std::string(PICDEM_SOURCE_DIR) + "/" + relative_path, overrides,
                         coupling::case_schema());
}

/// Prints (root rank) the resolution a validation ran at: the cell size, the grid, the particle
/// seeding and the ranks, so that every figure in the output names its resolution.
inline void print_resolution(const core::Comm& comm, const std::string& what,
                             const core::Params& params) {
  if (!comm.is_root()) return;
  const double h = params.real("grid/cell_size");
  std::printf(
      "%s: resolution h = %.4g m (%.0f x %.0f cells), %lld x %lld particles per cell, "
      "jitter %.2f, %d rank(s)\n",
      what.c_str(), h, params.real("grid/length") / h, params.real("grid/height") / h,
      static_cast<long long>(params.integer("particles/per_cell_1d")),
      static_cast<long long>(params.integer("particles/per_cell_1d")),
      params.real("particles/jitter"), comm.size());
}

}  // namespace picdem::test_support

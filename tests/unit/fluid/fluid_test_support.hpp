#pragma once
// Shared set-up of the fluid tests: the case parameters of a small tank, an all-fluid grid.
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid_test {

inline core::Params tank_params(double length, double height, double h,
                                const std::vector<std::string>& overrides = {}) {
  core::ParamSchema schema;
  grid::declare_parameters(schema);
  fluid::declare_parameters(schema);
  const std::string yaml = "grid:\n  length: " + std::to_string(length) +
                           "\n  height: " + std::to_string(height) +
                           "\n  cell_size: " + std::to_string(h) + "\n";
  return core::read_case_text(yaml, "fluid test", overrides, schema);
}

/// Every cell of the grid fluid, the ghost cells beyond the tank solid.
inline fluid::CellStates all_fluid(const grid::Decomposition& d) {
  fluid::CellStates c(d, grid::Stagger::Cell, static_cast<signed char>(grid::CellState::Solid));
  const auto& b = c.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && k >= 0 && i < d.spec().nx && k < d.spec().nz)
        c(i, k) = static_cast<signed char>(grid::CellState::Fluid);
  return c;
}

}  // namespace picdem::fluid_test

#pragma once
// Shared set-up of the fluid tests: the case parameters of a small tank.
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

}  // namespace picdem::fluid_test

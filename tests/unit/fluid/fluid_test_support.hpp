#pragma once
// Shared set-up of the fluid tests: the case parameters of a small tank, an all-fluid grid.
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid_test {

constexpr signed char kAir = static_cast<signed char>(grid::CellState::Air);
constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(grid::CellState::Solid);

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

/// What a pressure solve of the tank `params` reads: every cell air, open apertures, zero face
/// velocities, no solids (the tests fill them); one grid block per rank.
struct TankFields {
  grid::GridSpec s;
  grid::Decomposition d;
  grid::Halo halo;
  fluid::CellStates cells;
  fluid::Apertures E;
  grid::FaceField u, w;
  fluid::FluidConfig cfg;
  std::vector<fluid::SolidCoupling> solids;

  TankFields(const core::Params& params, const core::Comm& comm)
      : s(grid::spec_from(params)),
        d(s, comm, 1),
        halo(d),
        cells(d, grid::Stagger::Cell, kAir),
        E(fluid::open_apertures(d)),
        u(d, grid::Stagger::FaceX, 0.0),
        w(d, grid::Stagger::FaceZ, 0.0),
        cfg(fluid::config_from(params)) {}

  /// u and w on the owned faces uniform in [-0.1, 0.1) from `seed`, then the halos.
  void random_velocities(std::uint64_t seed) {
    for (grid::FaceField* f : {&u, &w})
      for (int k = f->owned().k0; k < f->owned().k1; ++k)
        for (int i = f->owned().i0; i < f->owned().i1; ++i)
          (*f)(i, k) = 0.2 * (core::uniform01(seed, f == &u, i, k) - 0.5);
    halo.forward(u), halo.forward(w);
  }
};

}  // namespace picdem::fluid_test

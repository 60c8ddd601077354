#pragma once
// Small builders shared by the DEM unit tests: one-rank solvers in a tank, disks and squares.
#include <cmath>
#include <memory>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::dem::testing {

inline core::Comm self() {
  return core::Comm(MPI_COMM_SELF);
}

inline SolidSpec disk(std::int64_t id, double r, double density, core::Vec2 x, core::Vec2 v = {},
                      double omega = 0.0) {
  SolidSpec s;
  s.shape = std::make_shared<const geometry::Circle>(r);
  s.density = density;
  s.state.id = id;
  s.state.x = x;
  s.state.v = v;
  s.state.omega = omega;
  return s;
}

inline std::shared_ptr<const geometry::Polygon> square_shape(double L) {
  return std::make_shared<const geometry::Polygon>(std::vector<core::Vec2>{
      {-0.5 * L, -0.5 * L}, {0.5 * L, -0.5 * L}, {0.5 * L, 0.5 * L}, {-0.5 * L, 0.5 * L}});
}

inline SolidSpec square(std::int64_t id, double L, double density, core::Vec2 x, double theta = 0.0,
                        core::Vec2 v = {}) {
  SolidSpec s;
  s.shape = square_shape(L);
  s.density = density;
  s.state.id = id;
  s.state.x = x;
  s.state.theta = theta;
  s.state.v = v;
  return s;
}

/// A one-rank solver in the tank [0, L] x [0, H].
inline DemSolver solver(const DemConfig& cfg, double L, double H,
                        std::vector<std::vector<core::Vec2>> obstacles = {}) {
  const core::Box2 tank{{0.0, 0.0}, {L, H}};
  return DemSolver(self(), cfg, {tank}, tank, std::move(obstacles));
}

/// A configuration with cell size h and no gravity.
inline DemConfig weightless(double h) {
  DemConfig c;
  c.h = h;
  c.gravity = {0.0, 0.0};
  return c;
}

/// Collision loads of these solids (ordered by id) in a 1 m x 1 m tank, evaluated once with the
/// fluid step dt.
inline std::vector<core::SolidLoads> collision_loads(const DemConfig& cfg,
                                                     const std::vector<SolidSpec>& solids,
                                                     double dt = 1e-4) {
  DemSolver s = solver(cfg, 1.0, 1.0);
  s.add_solids(solids);
  return s.predicted_collision_loads(dt);
}

inline double kinetic_energy(const std::vector<core::SolidState>& s) {
  double e = 0.0;
  for (const auto& b : s)
    e += 0.5 * b.mass * core::norm2(b.v) + 0.5 * b.inertia * b.omega * b.omega;
  return e;
}

}  // namespace picdem::dem::testing

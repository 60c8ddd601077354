// The forces phase on the fluid's state (step_forces.hpp).
#include "picdem/fluid/step_forces.hpp"

#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

namespace {

void add_scaled(grid::FaceField& a, const grid::FaceField& b, double s) {
  const auto& box = a.storage();
  for (int k = box.k0; k < box.k1; ++k)
    for (int i = box.i0; i < box.i1; ++i) a(i, k) += s * b(i, k);
}

}  // namespace

void add_forces_explicit(const FluidConfig& cfg, double dt, const grid::Decomposition& d,
                         const grid::Halo& halo, FluidState& f) {
  apply_gravity(f.u, f.w, f.cells, dt, cfg);
  apply_viscosity(f.u, f.w, f.cells, dt, cfg, d, halo);
  enforce_walls(f.u, f.w, cfg, d);
}

ViscousExchange add_forces_implicit(const FluidConfig& cfg, std::vector<ViscousBody> bodies,
                                    const std::vector<core::SolidState>& solids,
                                    const std::vector<core::SolidState>& owned, bool rigid_rows,
                                    double dt, const SurfaceFractions* surface,
                                    const grid::Decomposition& d, const grid::Halo& halo,
                                    const core::Comm& comm, FluidState& f) {
  // Viscosity on u^n, then gravity: the implicit solve would diffuse g dt against the walls and
  // bodies into a rotational field the projection cannot remove (doc/viscous.md).
  for (std::size_t o = 0; o < cfg.obstacle_free_slip.size(); ++o)  // obstacles/<name>/wall
    bodies[solids.size() + o].free_slip = cfg.obstacle_free_slip[o] != 0;
  // With the pressure predictor the solve takes u + du, du = dt (g - grad p^n / rho), and
  // the result gives du back (doc/viscous.md, "Pressure predictor"); not with rigid rows, whose
  // solids would need the same prediction of the rest of their step.
  const bool predict = cfg.viscous_pressure_predictor && !rigid_rows;
  if (cfg.viscous_rotation_rows && !rigid_rows)  // omega an unknown, translation split
    for (std::size_t b = 0; b < solids.size(); ++b) {
      bodies[b].mass = solids[b].mass, bodies[b].inertia = solids[b].inertia;
      bodies[b].rotation_only = true;
    }
  grid::FaceField du(f.u), dw(f.w);
  if (predict) {
    viscous_pressure_predictor(du, dw, f.p, f.cells, f.apertures, dt, cfg, surface, d, halo);
    add_scaled(f.u, du, 1.0), add_scaled(f.w, dw, 1.0);
  }
  const auto step =
      apply_viscosity_implicit(f.u, f.w, f.cells, dt, cfg, d, halo, bodies, cfg.viscous_beta);
  if (predict) add_scaled(f.u, du, -1.0), add_scaled(f.w, dw, -1.0);
  const std::size_t obstacles = bodies.size() - solids.size();
  ViscousExchange viscous = viscous_exchange(solids, obstacles, step.loads, owned, comm);
  f.viscous_wall_force = step.loads.wall_force;
  apply_gravity(f.u, f.w, f.cells, dt, cfg);  // on owned faces: the halo follows
  halo.forward_all({&f.u, &f.w});
  enforce_walls(f.u, f.w, cfg, d);
  return viscous;
}

}  // namespace picdem::fluid

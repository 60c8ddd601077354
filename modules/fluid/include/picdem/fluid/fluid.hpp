#pragma once
// Fluid phases on the staggered grid (paper section 2.1, eqs. 1-5), apart from the pressure
// solve (pressure_solver.hpp):
//   forces     : u~ = u + dt g + dt nu lap(u)                      (eq. 2 without advection)
//   walls      : u.n = 0 on the tank walls, tangential ghosts for free-slip / no-slip
//   divergence : D_c = sum over faces (+/-) E_f u_f                  (eq. 5 right-hand side)
//   project    : u = u~ - dt/rho grad p on open faces next to fluid
//   extension  : fluid velocities copied into air faces, layer by layer
// All functions work on the owned samples of this rank; halo values are read where stencils
// need them, so the caller forwards the halo of inputs first unless a function says otherwise.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/fluid/open_boundary.hpp"
#include "picdem/fluid/viscous_settings.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid {

/// Declares fluid/density, fluid/viscosity, fluid/gravity, fluid/walls, fluid/wall_left,
/// fluid/wall_right, fluid/wall_bottom, fluid/wall_top, fluid/viscosity_scheme, the solver/ keys,
/// the viscous_solver/ keys (viscous_settings.hpp) and the open/ keys (open_boundary.hpp).
void declare_parameters(core::ParamSchema& schema);
/// Declares free_surface/method, free_surface/theta_min, free_surface/theta_open_length,
/// free_surface/density_correction and
/// free_surface/density_correction_interval (src/parameters.cpp).
void declare_free_surface_parameters(core::ParamSchema& schema);

/// The four tank walls, in the order of FluidConfig::wall_no_slip.
enum class TankWall { Left = 0, Right = 1, Bottom = 2, Top = 3 };

struct FluidConfig {
  double rho = 1000.0;       ///< density [kg/m^3]
  double nu = 1e-6;          ///< kinematic viscosity [m^2/s]
  core::Vec2 g{0.0, -9.81};  ///< gravity [m/s^2]
  bool no_slip = false;      ///< tank walls: no-slip (true) or free-slip (false)
  /// Per wall (left, right, bottom, top): its own condition, overriding no_slip; empty: no_slip.
  std::array<std::optional<bool>, 4> wall_no_slip{};
  bool implicit_viscosity = false;  ///< fluid/viscosity_scheme: implicit or crank_nicolson
  /// The implicit share beta of the theta scheme: 1 backward Euler (implicit), 1/2 Crank-Nicolson
  double viscous_beta = 1.0;
  /// fluid/viscous_pressure_predictor: the implicit viscous solve takes u + dt (g - grad p^n / rho)
  /// and removes it after (viscous_pressure_predictor, doc/viscous.md)
  bool viscous_pressure_predictor = false;
  /// fluid/viscous_cut_mass: the implicit step weighs each node by its P2G tent's share outside
  /// the bodies (set_cut_node_masses, doc/viscous.md "Cut-node masses")
  bool viscous_cut_mass = false;
  /// fluid/viscous_rotation_rows: without coupling/viscous_rigid_rows, each solid's omega is an
  /// unknown of the implicit viscous step (its translation stays split; doc/viscous.md)
  bool viscous_rotation_rows = false;
  /// viscous_solver/ keys: the implicit viscous solve's Belos and MueLu settings
  ViscousSolverSettings viscous_solver;
  double h = 0.0;       ///< cell size [m] (grid/cell_size)
  OpenBoundaries open;  ///< open/ keys: inflow and outflow sides (open_boundary.hpp)
  /// Per obstacle, in the case's order: obstacles/<name>/wall is free_slip (implicit viscosity,
  /// ViscousBody::free_slip).
  std::vector<char> obstacle_free_slip;
};
/// Reads the fluid/ keys and grid/cell_size (declared by grid::declare_parameters).
FluidConfig config_from(const core::Params& params);

/// The free_surface/ keys, read once.
struct FreeSurfaceConfig {
  bool ghost_fluid = true;          ///< method ghost_fluid (else p = 0 at air cell centres)
  double theta_min = 0.01;          ///< theta_min
  bool theta_open_length = false;   ///< theta_open_length (cut faces: theta >= theta_min h / E)
  double density_relaxation = 0.0;  ///< density_correction (0: off)
  long long density_interval = 1;   ///< density_correction_interval
  /// Whether the density is corrected at step `step`.
  bool corrects_density(long long step) const {
    return density_relaxation > 0.0 && step % density_interval == 0;
  }
};
FreeSurfaceConfig free_surface_config_from(const core::Params& params);

/// Whether tank wall `wall` is no-slip: its own setting, else FluidConfig::no_slip.
inline bool no_slip_at(const FluidConfig& cfg, TankWall wall) {
  const auto& own = cfg.wall_no_slip[static_cast<std::size_t>(wall)];
  return own ? *own : cfg.no_slip;
}

/// Ghost width the fluid stencils need (viscosity, projection, divergence): 1. Velocity
/// extension `layers` deep needs no more: it forwards the halo after every layer.
constexpr int required_halo() {
  return 1;
}

/// Values of grid::CellState (Air, Fluid, Solid) over owned + halo cells.
using CellStates = grid::GridArray<signed char>;

/// Open length of every face in [0, h]; 0 on the tank walls and where solids close a face.
struct Apertures {
  grid::FaceField E_x, E_z;
};
/// E = h on every interior face, 0 on the tank's outer faces (the walls), over owned + halo.
Apertures open_apertures(const grid::Decomposition& d);

/// Sub-cell free surface (ghost fluid): on a face between a fluid and an air cell, the fraction
/// theta in (0, 1] of the centre-to-centre distance that lies in the fluid; p = 0 is imposed at
/// that distance instead of at the air cell's centre. 1 on every other face.
struct SurfaceFractions {
  grid::FaceField theta_x, theta_z;
};
/// theta = phi_fluid / (phi_fluid - phi_air) from a cell-centred level set phi (< 0 in fluid),
/// clamped to [theta_min, 1], over the storage faces whose two cells are in storage. phi and
/// cells need a current halo.
SurfaceFractions surface_fractions(const grid::CellField& phi, const CellStates& cells,
                                   const grid::Decomposition& d, double theta_min = 0.01);

/// Adds dt g to every owned face next to a fluid cell (cells' halo must be current). Faces on the
/// tank walls are included: call enforce_walls afterwards, as the step does before the solve.
void apply_gravity(grid::FaceField& u, grid::FaceField& w, const CellStates& cells, double dt,
                   const FluidConfig& cfg);

/// Explicit viscosity u += dt nu lap(u) on interior faces between two fluid cells. Forwards the
/// halo of u and w and sets the wall ghosts itself. Neighbours that are not next to fluid (the
/// free surface) are replaced by the face's own value: zero normal gradient there.
void apply_viscosity(grid::FaceField& u, grid::FaceField& w, const CellStates& cells, double dt,
                     const FluidConfig& cfg, const grid::Decomposition& d, const grid::Halo& halo);

/// Normal velocity 0 on the tank walls; in the ghost layers outside the tank, the tangential
/// component is mirrored (free-slip: u_ghost = u_inside, no-slip: u_ghost = -u_inside) and the
/// normal component is odd about the wall. Open sides (cfg.open): inflow faces get the inflow
/// velocity, outflow faces keep theirs (enforce_open_sides). Call after the halo is forwarded.
void enforce_walls(grid::FaceField& u, grid::FaceField& w, const FluidConfig& cfg,
                   const grid::Decomposition& d);

/// D_c = E_x(i+1) u(i+1) - E_x(i) u(i) + E_z(k+1) w(k+1) - E_z(k) w(k) on owned fluid cells
/// (eq. 5 right-hand side without the solid term), 0 elsewhere. Units m^2/s (per unit depth).
void divergence(const grid::FaceField& u, const grid::FaceField& w, const Apertures& E,
                const CellStates& cells, grid::CellField& D);

/// u -= dt/rho (p_right - p_left)/h on owned open faces (E > 0, not on the walls) next to a fluid
/// cell and not next to a solid cell; p = 0 in air cells (eq. 3), or, with `surface`, at the
/// fraction theta of the way to the air cell (the same surface as passed to the solve). p's halo
/// must be current.
void project(grid::FaceField& u, grid::FaceField& w, const grid::CellField& p,
             const CellStates& cells, const Apertures& E, double dt, const FluidConfig& cfg,
             const SurfaceFractions* surface = nullptr);

/// Faces that carry fluid velocity: interior faces next to a fluid cell, with E > 0 (1), else 0.
void fluid_faces(const CellStates& cells, const Apertures& E, grid::GridArray<signed char>& u_valid,
                 grid::GridArray<signed char>& w_valid);

/// Extends velocities from valid faces into invalid ones, `layers` deep: each layer gives every
/// invalid face with valid neighbours (same component, 4-neighbourhood) their mean and marks it
/// valid. The validity arrays are copied, not changed. The result is that of forwarding the halo
/// after every layer, bit for bit; computed with one forward per halo width of layers, and after
/// the first layer only on the band next to the faces the previous layer reached.
void extend_velocity(grid::FaceField& u, grid::FaceField& w,
                     const grid::GridArray<signed char>& u_valid,
                     const grid::GridArray<signed char>& w_valid, int layers,
                     const grid::Halo& halo);

/// max(|u|, |w|) over all ranks' owned faces.
double max_face_speed(const grid::FaceField& u, const grid::FaceField& w, const core::Comm& comm);

/// dt = min(dt_max, cfl h / max|u|) over all ranks' owned faces.
double cfl_time_step(const grid::FaceField& u, const grid::FaceField& w, double h, double cfl,
                     double dt_max, const core::Comm& comm);

}  // namespace picdem::fluid

#pragma once
// The fluid's state on this rank's grid window (owned + halo): the fields the step's fluid phases
// read and write, the history a checkpoint keeps (for_each_saved), and the read-only probes of
// tests and diagnostics. The step (coupling) decides the order of the phases; the fields live
// here.
#include "picdem/core/comm.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::fluid {

struct FluidState {
  FluidState() = default;
  /// Every field on the decomposition's storage window: velocities 0, every cell air, the tank's
  /// apertures (fluid::open_apertures).
  explicit FluidState(const grid::Decomposition& d);

  grid::FaceField u, w;                           ///< u^n, then u~, then u^{n+1}
  grid::FaceField u_old, w_old;                   ///< u~ before forces: the FLIP increment's base
  grid::FaceField weight_u, weight_w;             ///< P2G weights
  grid::GridArray<signed char> u_valid, w_valid;  ///< faces carrying a known velocity
  grid::CellField p;                              ///< pressure; the next solve's initial guess
  CellStates cells;                               ///< grid::CellState of every cell
  grid::CellField occupancy;                      ///< S of the particles (free_surface.hpp)
  grid::CellField phi;       ///< level set 1/2 - S (open-volume corrected), < 0 in the fluid
  SurfaceFractions surface;  ///< ghost-fluid fractions of the faces crossing the free surface
  Apertures apertures;       ///< open lengths E of the faces (tank walls, cut cells)
  /// The fluid's viscous force on the tank walls in the last step's implicit viscous solve, per
  /// unit depth (ViscousLoads::wall_force); zero with the explicit scheme. Not saved.
  core::Vec2 viscous_wall_force;

  /// The history a checkpoint keeps, in one place: f(name, array) for u, w, p (double) and cells
  /// (signed char), each over the storage window. Everything else is recomputed by the step
  /// before it is read.
  template <class F>
  void for_each_saved(F&& f) {
    f("u", u), f("w", w), f("p", p), f("cells", cells);
  }
  template <class F>
  void for_each_saved(F&& f) const {
    f("u", u), f("w", w), f("p", p), f("cells", cells);
  }

  // Probes (collective: every rank gets the same answer).

  /// Pressure of the cell holding x (the owning rank's value).
  double pressure_at(core::Vec2 x) const;
  /// Force of the pressure on the tank's walls on the fluid, per unit depth: the pressure of the
  /// fluid cells next to a wall, carried hydrostatically to it (the bottom's half cell), times
  /// the wall's length in those cells.
  core::Vec2 wall_pressure_force(const FluidConfig& cfg) const;
  /// Largest speed on the faces that carry fluid velocity (fluid::fluid_faces).
  double max_grid_speed() const;
  /// Height of the free surface (occupancy S = 1/2) in the column holding x: the highest crossing
  /// from fluid below to air above, linear between cell centres; NaN when the column has none.
  double surface_height(double x) const;

 private:
  const grid::Decomposition* d_ = nullptr;
};

/// Collective: `f` moved from the blocks of `from` to those of `to` (new cut lines): the fields a
/// checkpoint keeps (for_each_saved) with their ghosts (grid::redistributed); every other field
/// starts over as in FluidState(to) (the step recomputes them before reading). `to` must
/// outlive the result.
FluidState redistributed(const FluidState& f, const grid::Decomposition& from,
                         const grid::Decomposition& to);

}  // namespace picdem::fluid

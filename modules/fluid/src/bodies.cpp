#include "picdem/fluid/bodies.hpp"

#include <algorithm>
#include <utility>

#include "picdem/fluid/free_surface.hpp"
#include "picdem/grid/axis.hpp"

namespace picdem::fluid {

using core::Vec2;
using grid::Axis;
using grid::CellState;
using grid::Stagger;

namespace {
/// The bodies' aperture of the face (i, k) normal to axis a.
double cut_aperture(const geometry::CutCells& cut, Axis a, int i, int k) {
  return a == Axis::X ? cut.E_x(i, k) : cut.E_z(i, k);
}
}  // namespace

void mark_cells(const grid::GridArray<int>& count, const geometry::CutCells* cut,
                const grid::Decomposition& d, const grid::Halo& halo, bool ghost_fluid,
                double theta_min, bool theta_open_length, FluidState& f) {
  if (cut) open_share_correction(f.occupancy, *cut, d);
  const auto b = f.cells.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      CellState c = count(i, k) > 0 ? CellState::Fluid : CellState::Air;
      const double S = f.occupancy(i, k);
      if (cut) {
        const double frac = cut->fluid_fraction(i, k);
        if (frac <= 0.0)
          c = CellState::Solid;
        else if (c == CellState::Air && frac < 1.0 && S > 0.5)
          c = CellState::Fluid;
      }
      f.phi(i, k) = 0.5 - S;
      f.cells(i, k) = static_cast<signed char>(c);
    }
  if (cut) {
    wet_enclosed_cut_cells(d, *cut, f.apertures, f.cells);
    // A group reaching the edge of one rank's window is seen whole by its owner: owners decide.
    halo.forward(f.cells);
  }
  if (ghost_fluid) {
    f.surface = surface_fractions(f.phi, f.cells, d, theta_min);
    if (cut && theta_open_length)
      open_length_surface_fractions(*cut, theta_min, d.spec().h, f.surface);
  }
}

// On a fluid-air face a body cuts, eq. 5 weighs the ghost-fluid gradient p / (theta h) by the
// open length E, so a small E leaves the fluid cell's pressure to its other faces, and that
// gradient, up to 1 / theta_min times the cell's own, is spent as velocity on the face:
// 52.6 m/s through E = 0.027 h at theta = theta_min, p = 3.7 kPa, beside a cylinder entering the
// water in a fall pipe at h = 1.5 mm (doc/coupling.md, "The free surface on cut faces").
// theta >= theta_min h / E bounds that velocity by E / h times a full face's.
void open_length_surface_fractions(const geometry::CutCells& cut, double theta_min, double h,
                                   SurfaceFractions& s) {
  auto raise = [&](double& theta, double E) {
    if (theta < 1.0 && E > 0.0 && E < h) theta = std::max(theta, std::min(1.0, theta_min * h / E));
  };
  // theta < 1 only on fluid-air faces, whose two cells are in storage (surface_fractions)
  const auto bx = s.theta_x.storage();
  for (int k = bx.k0; k < bx.k1; ++k)
    for (int i = bx.i0; i < bx.i1; ++i) raise(s.theta_x(i, k), cut.E_x(i, k));
  const auto bz = s.theta_z.storage();
  for (int k = bz.k0; k < bz.k1; ++k)
    for (int i = bz.i0; i < bz.i1; ++i) raise(s.theta_z(i, k), cut.E_z(i, k));
}

// A cut cell whose sliver of fluid holds no particle, with S <= 1/2 at its (covered) centre, would
// be air: p = 0 inside the water, and a pressure jump that drives the flow through its faces at
// many times the speed around it. Such cells are taken in groups connected through open faces
// (two slivers side by side on a body); a group whose every other neighbour across an open face
// is fluid (or solid) cannot be at the free surface: it is fluid.
void wet_enclosed_cut_cells(const grid::Decomposition& d, const geometry::CutCells& cut,
                            const Apertures& E, CellStates& cells) {
  const auto wet = static_cast<signed char>(CellState::Fluid);
  const auto air = static_cast<signed char>(CellState::Air);
  const auto solid = static_cast<signed char>(CellState::Solid);
  const auto& spec = d.spec();
  const auto b = cells.storage();
  auto candidate = [&](int i, int k) {
    return cells.in_storage(i, k) && cells(i, k) == air && cut.fluid_fraction(i, k) < 1.0;
  };
  grid::GridArray<signed char> seen(d, Stagger::Cell, 0);
  std::vector<std::pair<int, int>> group, todo;
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      if (seen(i, k) || !candidate(i, k)) continue;
      group.clear();
      todo.assign(1, {i, k});
      seen(i, k) = 1;
      bool enclosed = true;
      while (!todo.empty()) {
        const auto [ci, ck] = todo.back();
        todo.pop_back();
        group.emplace_back(ci, ck);
        const struct {
          double E;
          int i, k;
        } faces[4] = {{E.E_x(ci, ck), ci - 1, ck},
                      {E.E_x(ci + 1, ck), ci + 1, ck},
                      {E.E_z(ci, ck), ci, ck - 1},
                      {E.E_z(ci, ck + 1), ci, ck + 1}};
        for (const auto& face : faces) {
          if (face.E <= 0.0 || face.i < 0 || face.k < 0 || face.i >= spec.nx || face.k >= spec.nz)
            continue;
          if (!cells.in_storage(face.i, face.k)) {
            enclosed = false;  // the group reaches the edge of this rank's window
            continue;
          }
          if (candidate(face.i, face.k)) {
            if (!seen(face.i, face.k)) seen(face.i, face.k) = 1, todo.emplace_back(face.i, face.k);
            continue;
          }
          const signed char nb = cells(face.i, face.k);
          enclosed = enclosed && (nb == wet || nb == solid);
        }
      }
      if (enclosed)
        for (const auto& [gi, gk] : group) cells(gi, gk) = wet;
    }
}

Apertures body_apertures(const geometry::CutCells& cut, const grid::Decomposition& d) {
  Apertures E = open_apertures(d);
  for (const Axis a : grid::kAxes) {
    grid::FaceField& e = along(a, E.E_x, E.E_z);
    // faces outside the cut cells' storage are open (h), which leaves e as it is
    const auto& st = cut.store;
    const auto b = e.storage().intersect(
        {st.i0, st.i1 + (a == Axis::X ? 1 : 0), st.k0, st.k1 + (a == Axis::Z ? 1 : 0)});
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) e(i, k) = std::min(e(i, k), cut_aperture(cut, a, i, k));
  }
  return E;
}

geometry::CutCells cut_cells(const std::vector<geometry::SolidPlacement>& solids,
                             const std::vector<geometry::Obstacle>& obstacles, double tiny_fraction,
                             const grid::Decomposition& d, Apertures& apertures) {
  const auto& spec = d.spec();
  geometry::GridWindow window{spec.origin, spec.h, d.storage(grid::Stagger::Cell)};
  geometry::CutCellOptions options;
  options.tiny_fraction = tiny_fraction;
  auto cut = geometry::build_cut_cells(window, solids, obstacles, options);
  apertures = body_apertures(cut, d);
  return cut;
}

namespace {

/// Visits every interior face (storage) beside a cell cut by a body or an obstacle:
/// fn(axis, i, k, U_n) with U_n the normal component of the covering body's rigid velocity
/// v + omega x r at the face's centre (0 for an obstacle), bodies[b] the motion of cut body b.
template <class Fn>
void for_faces_by_bodies(const std::vector<core::SolidState>& bodies, const geometry::CutCells& cut,
                         const grid::Decomposition& d, Fn&& fn) {
  const auto& spec = d.spec();
  auto rigid = [&](int body, Vec2 x) {
    if (body < 0) return Vec2{};
    const auto& st = bodies[static_cast<std::size_t>(body)];
    return st.v + core::cross(st.omega, x - st.x);
  };
  // The body covering either cell beside a face, the low cell's first. A face on the window's
  // edge has one cell in the ring outside it, which the cut cells know as well: every rank picks
  // the body a whole-grid window would.
  auto covering = [&](int i0, int k0, int i1, int k1, bool& any) {
    int body = cut.cutting_body(i0, k0);
    if (body < 0) body = cut.cutting_body(i1, k1);
    any = body >= 0 || cut.cutting_obstacle(i0, k0) >= 0 || cut.cutting_obstacle(i1, k1) >= 0;
    return body;
  };
  for (const Axis a : grid::kAxes) {
    // the face (i, k) normal to a lies between the cells (i - di, k - dk) and (i, k)
    const int di = grid::step_i(a), dk = grid::step_k(a);
    const auto b = d.storage(face_stagger(a));
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        if (i - di < 0 || i >= spec.nx || k - dk < 0 || k >= spec.nz) continue;
        bool any = false;
        const int body = covering(i - di, k - dk, i, k, any);
        if (!any) continue;
        fn(a, i, k,
           [&] { return component(rigid(body, spec.position(face_stagger(a), i, k)), a); });
      }
  }
}

}  // namespace

void rigid_face_velocities(const std::vector<core::SolidState>& bodies,
                           const geometry::CutCells& cut, const Apertures& E,
                           const grid::Decomposition& d, grid::FaceField& u, grid::FaceField& w,
                           grid::GridArray<signed char>& u_valid,
                           grid::GridArray<signed char>& w_valid) {
  for_faces_by_bodies(bodies, cut, d, [&](Axis a, int i, int k, auto rigid_normal) {
    if (along(a, E.E_x, E.E_z)(i, k) > 0.0) return;
    along(a, u, w)(i, k) = rigid_normal();
    along(a, u_valid, w_valid)(i, k) = 1;
  });
}

void mix_cut_faces(const std::vector<core::SolidState>& bodies, const geometry::CutCells& cut,
                   const grid::Decomposition& d, FluidState& f) {
  const double h = d.spec().h;
  for_faces_by_bodies(bodies, cut, d, [&](Axis a, int i, int k, auto rigid_normal) {
    const double e = along(a, f.apertures.E_x, f.apertures.E_z)(i, k) / h;
    if (!(e > 0.0 && e < 1.0)) return;
    const double U = rigid_normal();
    double& now = along(a, f.u, f.w)(i, k);
    double& old = along(a, f.u_old, f.w_old)(i, k);
    now = e * now + (1.0 - e) * U;
    old = e * old + (1.0 - e) * U;
  });
}

void extend_around_fluid(const std::vector<core::SolidState>& motions,
                         const geometry::CutCells* cut, const grid::Decomposition& d,
                         const grid::Halo& halo, bool recompute_mask, FluidState& f) {
  if (recompute_mask) fluid_faces(f.cells, f.apertures, f.u_valid, f.w_valid);
  if (cut) rigid_face_velocities(motions, *cut, f.apertures, d, f.u, f.w, f.u_valid, f.w_valid);
  extend_velocity(f.u, f.w, f.u_valid, f.w_valid, d.halo(), halo);
}

void rigid_faces_into_flip_base(const grid::GridSpec& spec, FluidState& f) {
  for (const Axis a : grid::kAxes) {
    const grid::FaceField& vel = along(a, f.u, f.w);
    grid::FaceField& old = along(a, f.u_old, f.w_old);
    const grid::FaceField& aperture = along(a, f.apertures.E_x, f.apertures.E_z);
    // faces inside the tank along a (the walls' faces keep their base)
    const int n = a == Axis::X ? spec.nx : spec.nz;
    const auto b = vel.storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        const int j = a == Axis::X ? i : k;
        if (j > 0 && j < n && aperture(i, k) <= 0.0) old(i, k) = vel(i, k);
      }
  }
}

CellStates reseed_cells(const CellStates& cells, const geometry::CutCells& cut) {
  CellStates out = cells;
  const auto b = out.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (cut.fluid_fraction(i, k) < 1.0) out(i, k) = static_cast<signed char>(CellState::Solid);
  return out;
}

}  // namespace picdem::fluid

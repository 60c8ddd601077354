#include "picdem/fluid/free_surface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "picdem/grid/tent.hpp"

namespace picdem::fluid {

void open_share_correction(grid::CellField& S, const geometry::CutCells& cut,
                           const grid::Decomposition& d) {
  const auto b = S.storage();
  const auto ext = d.spec().extent(grid::Stagger::Cell);
  // The tent's mass (per axis) in the cell's left or lower neighbour, the cell, the other one.
  const double tent[3] = {grid::tent_share(-1.5, -0.5), grid::tent_share(-0.5, 0.5),
                          grid::tent_share(0.5, 1.5)};
  // Where the cell and its neighbours are all fluid, open = all exactly and S is unchanged: only
  // cells next to a cut or covered cell are visited. S(i, k) is the only value of S read for
  // cell (i, k), so S is corrected in place.
  const auto nx = static_cast<std::size_t>(b.nx());
  std::vector<unsigned char> near(static_cast<std::size_t>(b.size()), 0);
  // the cut cells' storage (geometry::CutCells::store): every cell outside it has fraction 1
  const auto& st = cut.store;
  const auto cut_part = b.intersect(st);
  for (int k = cut_part.k0; k < cut_part.k1; ++k)
    for (int i = cut_part.i0; i < cut_part.i1; ++i) {
      if (cut.fraction[static_cast<std::size_t>(k - st.k0) * static_cast<std::size_t>(st.nx()) +
                       static_cast<std::size_t>(i - st.i0)] == 1.0)
        continue;
      for (int kk = std::max(k - 1, b.k0); kk < std::min(k + 2, b.k1); ++kk)
        for (int ii = std::max(i - 1, b.i0); ii < std::min(i + 2, b.i1); ++ii)
          near[static_cast<std::size_t>(kk - b.k0) * nx + static_cast<std::size_t>(ii - b.i0)] = 1;
    }
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) {
      if (!near[static_cast<std::size_t>(k - b.k0) * nx + static_cast<std::size_t>(i - b.i0)] ||
          S(i, k) == 0.0)
        continue;
      double open = 0.0, all = 0.0;
      for (int bb = -1; bb <= 1; ++bb)
        for (int aa = -1; aa <= 1; ++aa) {
          if (!ext.contains(i + aa, k + bb) || !S.in_storage(i + aa, k + bb)) continue;
          const double wgt = tent[aa + 1] * tent[bb + 1];
          open += wgt * cut.fluid_fraction(i + aa, k + bb);
          all += wgt;
        }
      if (open > 0.05 * all) S(i, k) = S(i, k) * all / open;
    }
}

namespace {

// Length of {x in [x0, x0 + len] : a + b x > 1/2}: continuous in a and b except at b = 0,
// a = 1/2 exactly (a level line lying on the segment).
double length_above_half(double a, double b, double x0, double len) {
  if (b == 0.0) return a > 0.5 ? len : 0.0;
  const double cross = std::clamp((0.5 - a) / b, x0, x0 + len);
  return b > 0.0 ? x0 + len - cross : cross - x0;
}

}  // namespace

double occupied_area(const grid::CellField& S, const grid::Decomposition& d, const core::Comm& comm,
                     const geometry::CutCells* cut) {
  const auto& spec = d.spec();
  const auto own = d.owned_cells();
  // S at a centre, mirrored across the tank walls.
  auto at = [&](int i, int k) {
    i = std::clamp(i, 0, spec.nx - 1);
    k = std::clamp(k, 0, spec.nz - 1);
    return S(i, k);
  };
  // Lines per quarter cell in cells the surface crosses. Along each line (z fixed) the bilinear
  // interpolant is linear in x and the length where it exceeds 1/2 is exact, so the area is a
  // continuous function of S: round-off in S changes it by round-off, where a count of sample
  // points above 1/2 jumps by a sample's area (doc/validation.md).
  constexpr int lines = 4;
  // A cell adds area only when S > 1/2 somewhere in its 3 x 3 block: cells farther than one from
  // the box of such cells (on the grid, within the storage) add nothing and are not visited.
  const auto st = S.storage().intersect(spec.extent(grid::Stagger::Cell));
  core::IndexBox wet{st.i1, st.i0, st.k1, st.k0};
  for (int k = st.k0; k < st.k1; ++k)
    for (int i = st.i0; i < st.i1; ++i)
      if (S(i, k) > 0.5)
        wet = {std::min(wet.i0, i), std::max(wet.i1, i + 1), std::min(wet.k0, k),
               std::max(wet.k1, k + 1)};
  const auto visit = own.intersect(wet.grown(1));
  double area_cells = 0.0;
  for (int k = visit.k0; k < visit.k1; ++k)
    for (int i = visit.i0; i < visit.i1; ++i) {
      double lo = 1e300, hi = -1e300;
      for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a)
          lo = std::min(lo, at(i + a, k + b)), hi = std::max(hi, at(i + a, k + b));
      const double f = cut ? cut->fluid_fraction(i, k) : 1.0;
      if (lo > 0.5) {  // the interpolant exceeds 1/2 on the whole cell
        area_cells += f;
        continue;
      }
      if (hi <= 0.5 || f <= 0.0) continue;
      double inside = 0.0;
      // quarter (a, b) of the cell lies in the square between centres (i + a, k + b) and
      // (i + a + 1, k + b + 1), a, b in {-1, 0}; there its local coordinates run over
      // [x0, x0 + 1/2] x [z0, z0 + 1/2] with x0 = -a / 2, z0 = -b / 2
      for (int b = -1; b <= 0; ++b)
        for (int a = -1; a <= 0; ++a) {
          const double s00 = at(i + a, k + b), s10 = at(i + a + 1, k + b);
          const double s01 = at(i + a, k + b + 1), s11 = at(i + a + 1, k + b + 1);
          for (int q = 0; q < lines; ++q) {
            const double fz = -0.5 * b + 0.5 * (q + 0.5) / lines;
            // s(x) = (1 - fz)(s00 + (s10 - s00) x) + fz (s01 + (s11 - s01) x)
            const double s0 = (1 - fz) * s00 + fz * s01;
            const double slope = (1 - fz) * (s10 - s00) + fz * (s11 - s01);
            inside += length_above_half(s0, slope, -0.5 * a, 0.5) * (0.5 / lines);
          }
        }
      area_cells += f * inside;
    }
  return comm.sum(area_cells) * spec.h * spec.h;
}

bool excess_area(const grid::CellField& S, const CellStates& cells, const geometry::CutCells* cut,
                 double relaxation, double cap, const grid::Decomposition& d,
                 grid::CellField& source) {
  const auto wet = static_cast<signed char>(grid::CellState::Fluid);
  const auto air = static_cast<signed char>(grid::CellState::Air);
  const auto& spec = d.spec();
  const auto own = d.owned_cells();
  const auto ext = spec.extent(grid::Stagger::Cell);
  const double area = spec.h * spec.h;
  source.fill(0.0);
  bool any = false;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      if (cells(i, k) != wet) continue;
      const double excess = std::clamp(S(i, k) - 1.0, -cap, cap);
      if (excess < 0.0) {
        bool inside = true;
        for (int b = -1; b <= 1 && inside; ++b)
          for (int a = -1; a <= 1 && inside; ++a)
            inside = !ext.contains(i + a, k + b) || cells(i + a, k + b) != air;
        if (!inside) continue;
      }
      const double f = cut ? cut->fluid_fraction(i, k) : 1.0;
      source(i, k) = relaxation * excess * f * area;
      any = any || source(i, k) != 0.0;
    }
  return any;
}

// Closed faces (walls, bodies) hold 0 and count as known; the rest is extended.
void extend_displacement(const CellStates& cells, const Apertures& apertures,
                         const FluidConfig& unit, const grid::Decomposition& d,
                         const grid::Halo& halo, grid::FaceField& dx, grid::FaceField& dz) {
  grid::GridArray<signed char> du(d, grid::Stagger::FaceX, 0), dw(d, grid::Stagger::FaceZ, 0);
  fluid_faces(cells, apertures, du, dw);
  for (auto [valid, E] : {std::pair{&du, &apertures.E_x}, std::pair{&dw, &apertures.E_z}}) {
    const auto b = valid->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        if ((*E)(i, k) <= 0.0) (*valid)(i, k) = 1;
  }
  halo.forward_all({&dx, &dz});
  enforce_walls(dx, dz, unit, d);
  extend_velocity(dx, dz, du, dw, d.halo(), halo);
}

}  // namespace picdem::fluid

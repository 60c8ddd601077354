// The open sides on the step's fields (open_flow.hpp, doc/open_boundaries.md).
#include "picdem/fluid/open_flow.hpp"

#include <cmath>
#include <limits>

namespace picdem::fluid {

using grid::FaceField;

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

/// Inward normal sign of a side: +1 left and bottom, -1 right and top.
double inward(std::size_t side) {
  return side == 0 || side == 2 ? 1.0 : -1.0;
}

/// The normal face index of a side (i on the left and right, k on the bottom and top).
int normal_index(const grid::GridSpec& g, std::size_t side) {
  return side == 0 ? 0 : (side == 1 ? g.nx : (side == 2 ? 0 : g.nz));
}

/// Calls f(field, along, normal_index, position) for every storage face of a side's normal
/// component that is open; `along` is the index along the side (k or i).
template <class Field, class F>
void for_open_faces(Field& field, const OpenSide& s, std::size_t side, const grid::GridSpec& g,
                    F&& f) {
  if (s.kind == OpenKind::Wall) return;
  const auto& b = field.storage();
  const int n = normal_index(g, side);
  const bool x_side = side < 2;
  const int lo = x_side ? b.k0 : b.i0, hi = x_side ? b.k1 : b.i1;
  for (int a = std::max(lo, 0); a < std::min(hi, side_faces(g, side)); ++a) {
    const int i = x_side ? n : a, k = x_side ? a : n;
    if (!field.in_storage(i, k) || !s.open_at(face_position(g, side, a))) continue;
    f(i, k, a);
  }
}

}  // namespace

void open_side_apertures(Apertures& E, const OpenBoundaries& o, const grid::Decomposition& d) {
  const grid::GridSpec& g = d.spec();
  for (std::size_t side = 0; side < 4; ++side) {
    FaceField& field = side < 2 ? E.E_x : E.E_z;
    for_open_faces(field, o.side[side], side, g, [&](int i, int k, int) { field(i, k) = g.h; });
  }
}

OutflowFaces keep_outflow_faces(const FaceField& u, const FaceField& w, const OpenBoundaries& o,
                                const grid::Decomposition& d) {
  const grid::GridSpec& g = d.spec();
  OutflowFaces kept;
  std::vector<double>* lists[4] = {&kept.u_left, &kept.u_right, &kept.w_bottom, &kept.w_top};
  for (std::size_t side = 0; side < 4; ++side) {
    if (o.side[side].kind != OpenKind::Outflow) continue;
    const FaceField& field = side < 2 ? u : w;
    auto& list = *lists[side];
    list.assign(static_cast<std::size_t>(side_faces(g, side)), kNone);
    for_open_faces(field, o.side[side], side, g,
                   [&](int i, int k, int a) { list[static_cast<std::size_t>(a)] = field(i, k); });
  }
  return kept;
}

void enforce_open_sides(FaceField& u, FaceField& w, const OpenBoundaries& o,
                        const grid::Decomposition& d, const OutflowFaces& kept) {
  const grid::GridSpec& g = d.spec();
  const std::vector<double>* lists[4] = {&kept.u_left, &kept.u_right, &kept.w_bottom, &kept.w_top};
  for (std::size_t side = 0; side < 4; ++side) {
    const OpenSide& s = o.side[side];
    if (s.kind == OpenKind::Wall) continue;
    const bool x_side = side < 2;
    FaceField& normal = x_side ? u : w;
    FaceField& tangential = x_side ? w : u;
    const int n = normal_index(g, side);
    const int out = side == 0 || side == 2 ? -1 : 1;  // the step outwards
    for_open_faces(normal, s, side, g, [&](int i, int k, int a) {
      double value;
      if (s.kind == OpenKind::Inflow) {
        value = inward(side) * o.face_speed(side, face_position(g, side, a));
      } else {
        value = (*lists[side])[static_cast<std::size_t>(a)];
        if (std::isnan(value)) return;
      }
      normal(i, k) = value;
      // ghosts beyond: the face's value (inflow: prescribed; outflow: zero normal gradient)
      for (int j = 1;; ++j) {
        const int gi = x_side ? i + out * j : i, gk = x_side ? k : k + out * j;
        if (!normal.in_storage(gi, gk)) break;
        normal(gi, gk) = value;
      }
    });
    // Tangential ghosts, mirrored about the side: -inside (inflow: no tangential velocity),
    // +inside (outflow: zero tangential gradient).
    const double t = s.kind == OpenKind::Inflow ? -1.0 : 1.0;
    const auto& b = tangential.storage();
    const double origin = x_side ? g.origin.z : g.origin.x;
    for (int a = x_side ? b.k0 : b.i0; a < (x_side ? b.k1 : b.i1); ++a) {
      if (!s.open_at(origin + a * g.h)) continue;
      for (int j = 0;; ++j) {
        // ghost at n + j (outwards) or n - 1 - j, mirrored from n - 1 - j or n + j
        const int ghost = out > 0 ? n + j : n - 1 - j, inside = out > 0 ? n - 1 - j : n + j;
        const int gi = x_side ? ghost : a, gk = x_side ? a : ghost;
        const int ii = x_side ? inside : a, ik = x_side ? a : inside;
        if (!tangential.in_storage(gi, gk)) break;
        if (tangential.in_storage(ii, ik)) tangential(gi, gk) = t * tangential(ii, ik);
      }
    }
  }
}

void zero_gradient_outflow(FaceField& u, FaceField& w, const OpenBoundaries& o,
                           const grid::Decomposition& d) {
  const grid::GridSpec& g = d.spec();
  for (std::size_t side = 0; side < 4; ++side) {
    const OpenSide& s = o.side[side];
    if (s.kind != OpenKind::Outflow || !s.zero_gradient) continue;
    const bool x_side = side < 2;
    FaceField& normal = x_side ? u : w;
    const int in = side == 0 || side == 2 ? 1 : -1;  // the step inwards
    for_open_faces(normal, s, side, g, [&](int i, int k, int) {
      const int ni = x_side ? i + in : i, nk = x_side ? k : k + in;
      // du_n / dn = 0: u_face = u_inside
      if (normal.in_storage(ni, nk)) normal(i, k) = normal(ni, nk);
    });
  }
}

void open_surface_fractions(SurfaceFractions& sf, const OpenBoundaries& o,
                            const grid::Decomposition& d) {
  const grid::GridSpec& g = d.spec();
  for (std::size_t side = 0; side < 4; ++side) {
    if (o.side[side].kind != OpenKind::Outflow) continue;
    FaceField& theta = side < 2 ? sf.theta_x : sf.theta_z;
    for_open_faces(theta, o.side[side], side, g, [&](int i, int k, int) { theta(i, k) = 0.5; });
  }
}

OpenFluxes open_fluxes(const FaceField& u, const FaceField& w, const CellStates& cells,
                       const SurfaceFractions* surface, const OpenBoundaries& o,
                       const grid::Decomposition& d, const core::Comm& comm) {
  const grid::GridSpec& g = d.spec();
  constexpr auto kFluid = static_cast<signed char>(grid::CellState::Fluid);
  constexpr auto kAir = static_cast<signed char>(grid::CellState::Air);
  double in = 0.0, out = 0.0;
  for (std::size_t side = 0; side < 4; ++side) {
    const OpenSide& s = o.side[side];
    if (s.kind == OpenKind::Wall) continue;
    const bool x_side = side < 2;
    const FaceField& field = x_side ? u : w;
    const auto& own = field.owned();
    // the cell inside a side's face (i, k): the face's own index on the left and bottom, one less
    // on the right and top
    const int di = side == 1 ? -1 : 0, dk = side == 3 ? -1 : 0;
    // the wet part of a face on one side of its cell's centre: h/2, or theta h up to the surface
    // when the neighbour along the side (cell (ci + ti, ck + tk), inside the tank) is air; the
    // face between the two cells holds theta (its index: the larger of the two cells')
    const auto wet_half = [&](int ci, int ck, int ti, int tk) {
      const int ni = ci + ti, nk = ck + tk;
      const bool beyond = ni < 0 || nk < 0 || ni >= g.nx || nk >= g.nz;  // the tank's wall
      if (!surface || beyond || !cells.in_storage(ni, nk) || cells(ni, nk) != kAir)
        return 0.5 * g.h;
      const FaceField& theta = x_side ? surface->theta_z : surface->theta_x;
      const int fi = std::max(ci, ni), fk = std::max(ck, nk);
      return std::min(0.5, theta(fi, fk)) * g.h;
    };
    for_open_faces(field, s, side, g, [&](int i, int k, int) {
      if (!own.contains(i, k)) return;
      // inward volume rate through the face: wet length times u.n_in
      const double un = inward(side) * field(i, k);
      if (s.kind == OpenKind::Inflow) {
        in += g.h * un;
        return;
      }
      const int ci = i + di, ck = k + dk;
      if (cells(ci, ck) != kFluid) return;
      const int ti = x_side ? 0 : 1, tk = x_side ? 1 : 0;
      out -= (wet_half(ci, ck, ti, tk) + wet_half(ci, ck, -ti, -tk)) * un;
    });
  }
  return {comm.sum(in), comm.sum(out)};
}

}  // namespace picdem::fluid

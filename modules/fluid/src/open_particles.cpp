// Particles at the open tank sides (open_particles.hpp).
#include "picdem/fluid/open_particles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "picdem/core/rng.hpp"

namespace picdem::fluid {

using core::Vec2;

namespace {

/// The point at distance `n` inside side `side` (inward) and at `s` along it.
Vec2 side_point(const grid::GridSpec& g, std::size_t side, double n, double s) {
  switch (side) {
    case 0:
      return {g.origin.x + n, s};
    case 1:
      return {g.origin.x + g.length() - n, s};
    case 2:
      return {s, g.origin.z + n};
    default:
      return {s, g.origin.z + g.height() - n};
  }
}

/// The boundary cell (i, k) of face f of a side.
std::array<int, 2> boundary_cell(const grid::GridSpec& g, std::size_t side, int f) {
  switch (side) {
    case 0:
      return {0, f};
    case 1:
      return {g.nx - 1, f};
    case 2:
      return {f, 0};
    default:
      return {f, g.nz - 1};
  }
}

}  // namespace

std::size_t mark_outflow_particles(const std::vector<double>& x, const std::vector<double>& z,
                                   const OpenBoundaries& open, const grid::GridSpec& g,
                                   std::vector<char>& keep) {
  // advect holds a leaving particle 1e-6 h inside the side: within 2e-6 h it has left
  const double band = 2e-6 * g.h;
  const double lo[4] = {g.origin.x, g.origin.x + g.length(), g.origin.z, g.origin.z + g.height()};
  std::size_t removed = 0;
  for (std::size_t side = 0; side < 4; ++side) {
    const OpenSide& s = open.side[side];
    if (s.kind != OpenKind::Outflow) continue;
    for (std::size_t n = 0; n < x.size(); ++n) {
      const double normal = side < 2 ? x[n] : z[n], along = side < 2 ? z[n] : x[n];
      if (!keep[n] || std::abs(normal - lo[side]) > band) continue;
      // the face holding the particle must be open
      const int f =
          static_cast<int>(std::floor((along - (side < 2 ? g.origin.z : g.origin.x)) / g.h));
      const int nf = side_faces(g, side);
      if (!s.open_at(face_position(g, side, std::clamp(f, 0, nf - 1)))) continue;
      keep[n] = 0;
      ++removed;
    }
  }
  return removed;
}

std::vector<InflowParticle> inflow_particles(const InflowSeeding& c, const OpenBoundaries& open,
                                             const grid::Decomposition& d,
                                             const std::function<bool(Vec2)>& reject) {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  const int n1 = c.per_cell_1d;
  const double sub = g.h / n1;
  const auto n_max = static_cast<std::int64_t>(std::max(g.nx, g.nz));
  // a seed of its own: the virtual columns never repeat the initial or reseeded positions
  const std::uint64_t seed = core::hash_counters(c.seed, 0x696e666c6f770000ULL);
  std::vector<InflowParticle> added;
  for (std::size_t side = 0; side < 4; ++side) {
    const OpenSide& s = open.side[side];
    if (s.kind != OpenKind::Inflow) continue;
    const double s_origin = side < 2 ? g.origin.z : g.origin.x;
    const double sign = side == 0 || side == 2 ? 1.0 : -1.0;
    for (int f = 0; f < side_faces(g, side); ++f) {
      const auto [bi, bk] = boundary_cell(g, side, f);
      if (!own.contains(bi, bk) || !s.open_at(face_position(g, side, f))) continue;
      const double s0 = s_origin + f * g.h, s1 = s0 + g.h;
      // columns j whose particles (normal coordinate in [-(j + 1) h, -j h]) may cross the side
      const auto before = s.displacement_bounds(s0, s1, open.t0);
      const auto after = s.displacement_bounds(s0, s1, open.t1);
      const auto j0 = static_cast<std::int64_t>(std::max(0.0, std::floor(before[0] / g.h) - 1.0));
      const auto j1 = static_cast<std::int64_t>(std::floor(after[1] / g.h) + 1.0);
      const double speed = sign;  // the velocity's sign along the inward normal's axis
      for (std::int64_t j = j0; j <= j1; ++j) {
        const auto cell =
            static_cast<std::uint64_t>((j * 4 + static_cast<std::int64_t>(side)) * n_max + f);
        for (int b = 0; b < n1; ++b)
          for (int a = 0; a < n1; ++a) {
            const auto n = static_cast<std::uint64_t>(b * n1 + a);
            // as particles::seed: (a + 1/2 + jitter (r - 1/2)) h / n1 in the virtual cell
            const double ra = core::uniform01(seed, cell, n, 0);
            const double rb = core::uniform01(seed, cell, n, 1);
            const double normal0 =
                -static_cast<double>(j + 1) * g.h + (a + 0.5 + c.jitter * (ra - 0.5)) * sub;
            const double along = s0 + (b + 0.5 + c.jitter * (rb - 0.5)) * sub;
            // x(t) = x0 + S(s, t): born when it crosses the side during the step
            const double n_now = normal0 + s.displacement(along, open.t1);
            if (!(n_now >= 0.0) || normal0 + s.displacement(along, open.t0) >= 0.0) continue;
            const Vec2 pos = side_point(g, side, std::max(n_now, 1e-6 * g.h), along);
            if (reject && reject(pos)) continue;
            const double v = speed * open.face_speed(side, along);
            const Vec2 vel = side < 2 ? Vec2{v, 0.0} : Vec2{0.0, v};
            const auto id =
                static_cast<std::int64_t>(cell) * n1 * n1 + static_cast<std::int64_t>(n);
            added.push_back({-(1 + id), pos, vel});
          }
      }
    }
  }
  return added;
}

}  // namespace picdem::fluid

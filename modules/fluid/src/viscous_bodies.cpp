// The solids and obstacles for the implicit viscous operator, and their loads by id
// (viscous_bodies.hpp).
#include "picdem/fluid/viscous_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "picdem/geometry/locator.hpp"

namespace picdem::fluid {

using core::Vec2;

namespace {

/// Inside any of the obstacle's polygons (its union when they do not overlap).
bool inside_polygons(const std::vector<std::vector<Vec2>>& polygons, const Vec2& p) {
  for (const auto& poly : polygons)
    if (geometry::inside_polygon(p, poly)) return true;
  return false;
}

/// The extent of the polygons' vertices, padded by 1e-9 of its size (an edge's crossing of a line
/// is rounded within it), as the body's box.
void padded_box(const std::vector<std::vector<Vec2>>& polygons, ViscousBody& body) {
  const double inf = std::numeric_limits<double>::infinity();
  Vec2 lo{inf, inf}, hi{-inf, -inf};
  for (const auto& poly : polygons)
    for (const Vec2& v : poly) {
      lo = {std::min(lo.x, v.x), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.z, v.z)};
    }
  if (!(lo.x <= hi.x)) return;  // no vertices: the box stays unbounded
  const double pad = 1e-9 * std::max({hi.x - lo.x, hi.z - lo.z, std::abs(lo.x), std::abs(lo.z),
                                      std::abs(hi.x), std::abs(hi.z)}) +
                     1e-12;
  body.box_lo = lo - Vec2{pad, pad};
  body.box_hi = hi + Vec2{pad, pad};
}

/// Position of solid `id` in `solids` (ordered by id); -1 when absent.
int index_of(const std::vector<core::SolidState>& solids, std::int64_t id) {
  const auto it =
      std::lower_bound(solids.begin(), solids.end(), id,
                       [](const core::SolidState& st, std::int64_t key) { return st.id < key; });
  return it != solids.end() && it->id == id ? static_cast<int>(it - solids.begin()) : -1;
}

}  // namespace

std::vector<ViscousBody> viscous_bodies(const std::vector<geometry::SolidPlacement>& placements,
                                        const std::vector<core::SolidState>& states,
                                        const std::vector<geometry::Obstacle>& obstacles,
                                        bool rigid_rows) {
  std::vector<ViscousBody> bodies;
  for (std::size_t b = 0; b < placements.size(); ++b) {
    const geometry::SolidPlacement& pl = placements[b];
    const core::SolidState& st = states[b];
    const geometry::ShapePtr shape = pl.shape;
    const geometry::Pose pose = pl.pose;
    bodies.push_back({[shape, pose](const Vec2& x) { return shape->contains(pose.to_body(x)); },
                      st.v, st.omega, pose.x, shape->mass_properties().area,
                      rigid_rows ? st.mass : 0.0, rigid_rows ? st.inertia : 0.0});
    // Every point of the body lies within its bounding radius of the centre (to_body's rounding
    // is far below the pad).
    const double r = shape->bounding_radius() * (1.0 + 1e-9) + 1e-12;
    bodies.back().box_lo = pose.x - Vec2{r, r};
    bodies.back().box_hi = pose.x + Vec2{r, r};
  }
  for (const geometry::Obstacle& o : obstacles) {
    const auto polygons = o.polygons;
    bodies.push_back(
        {[polygons](const Vec2& x) { return inside_polygons(polygons, x); }, {}, 0.0, {}, 0.0});
    padded_box(polygons, bodies.back());
  }
  return bodies;
}

ViscousExchange viscous_exchange(const std::vector<core::SolidState>& solids, std::size_t obstacles,
                                 const ViscousLoads& loads,
                                 const std::vector<core::SolidState>& owned,
                                 const core::Comm& comm) {
  ViscousExchange out;
  const std::size_t count = solids.size();
  if (loads.force.size() != count + obstacles) return out;  // nu = 0: none
  std::int64_t n = 0;
  for (const auto& st : solids) n = std::max(n, st.id + 1);
  n = static_cast<std::int64_t>(comm.max(static_cast<long long>(n)));
  // id -> (F_x, F_z, T), written by the owner only, then summed over the ranks
  std::vector<double> table(static_cast<std::size_t>(3 * n), 0.0);
  for (const auto& st : owned) {
    const int b = index_of(solids, st.id);
    if (b < 0) continue;
    double* r = &table[static_cast<std::size_t>(3 * st.id)];
    r[0] = loads.force[static_cast<std::size_t>(b)].x;
    r[1] = loads.force[static_cast<std::size_t>(b)].z;
    r[2] = loads.torque[static_cast<std::size_t>(b)];
  }
  comm.sum_in_place(table);
  for (std::int64_t id = 0; id < n; ++id) {
    const double* r = &table[static_cast<std::size_t>(3 * id)];
    out.solids.push_back({id, {r[0], r[1]}, r[2]});
  }
  for (std::size_t o = 0; o < obstacles; ++o)
    out.obstacles.push_back(
        {static_cast<std::int64_t>(o), loads.force[count + o], loads.torque[count + o]});
  return out;
}

std::vector<core::SolidLoads> plus_viscous(const std::vector<core::SolidLoads>& loads,
                                           const ViscousExchange& viscous,
                                           const std::vector<core::SolidState>& owned) {
  std::vector<core::SolidLoads> out = loads;
  for (const auto& st : owned) {
    if (st.id < 0 || static_cast<std::size_t>(st.id) >= viscous.solids.size()) continue;
    const core::SolidLoads& v = viscous.solids[static_cast<std::size_t>(st.id)];
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const core::SolidLoads& l) { return l.id == st.id; });
    if (it == out.end()) it = out.insert(out.end(), {st.id, {0.0, 0.0}, 0.0});
    it->force += v.force;
    it->torque += v.torque;
  }
  std::sort(out.begin(), out.end(),
            [](const core::SolidLoads& a, const core::SolidLoads& b) { return a.id < b.id; });
  return out;
}

}  // namespace picdem::fluid

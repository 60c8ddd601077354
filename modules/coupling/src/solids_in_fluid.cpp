#include "picdem/coupling/solids_in_fluid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

namespace picdem::coupling {

using core::Vec2;
using grid::CellState;
using grid::Stagger;

SolidScene scene_of(const dem::DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles) {
  SolidScene scene;
  scene.obstacles = obstacles;
  if (!dem) return scene;
  scene.states = dem->owned();
  const auto ghosts = dem->ghosts();
  scene.states.insert(scene.states.end(), ghosts.begin(), ghosts.end());
  std::sort(scene.states.begin(), scene.states.end(),
            [](const core::SolidState& a, const core::SolidState& b) { return a.id < b.id; });
  for (const auto& st : scene.states)
    scene.placements.push_back({st.id, dem->shape_of(st.id), {st.x, st.theta}});
  return scene;
}

int SolidScene::index_of(std::int64_t id) const {
  const auto it =
      std::lower_bound(states.begin(), states.end(), id,
                       [](const core::SolidState& st, std::int64_t key) { return st.id < key; });
  return it != states.end() && it->id == id ? static_cast<int>(it - states.begin()) : -1;
}

std::vector<core::SolidState> motions_at(const SolidScene& before, const SolidScene& after) {
  std::vector<core::SolidState> out = before.states;
  for (auto& st : out)
    if (const int n = after.index_of(st.id); n >= 0) st = after.states[static_cast<std::size_t>(n)];
  return out;
}

geometry::CutCells cut_cells(const SolidScene& scene, const grid::Decomposition& d,
                             double tiny_fraction, fluid::Apertures& apertures) {
  const auto& spec = d.spec();
  geometry::GridWindow window{spec.origin, spec.h, d.storage(Stagger::Cell)};
  geometry::CutCellOptions options;
  options.tiny_fraction = tiny_fraction;
  auto cut = geometry::build_cut_cells(window, scene.placements, scene.obstacles, options);
  apertures = fluid::open_apertures(d);
  const auto bu = apertures.E_x.storage();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i)
      apertures.E_x(i, k) = std::min(apertures.E_x(i, k), cut.E_x(i, k));
  const auto bw = apertures.E_z.storage();
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      apertures.E_z(i, k) = std::min(apertures.E_z(i, k), cut.E_z(i, k));
  return cut;
}

std::vector<dem::Contact> all_contacts(const dem::DemSolver& dem, const core::Comm& comm) {
  std::vector<double> mine;
  for (const auto& c : dem.active_contacts())
    mine.insert(mine.end(), {static_cast<double>(c.id_i), static_cast<double>(c.id_j), c.point.x,
                             c.point.z, c.normal.x, c.normal.z, c.delta});
  const auto all = comm.all_gather(mine);
  std::vector<dem::Contact> out;
  for (std::size_t n = 0; n + 7 <= all.size(); n += 7)
    out.push_back({static_cast<std::int64_t>(all[n]),
                   static_cast<std::int64_t>(all[n + 1]),
                   {all[n + 2], all[n + 3]},
                   {all[n + 4], all[n + 5]},
                   all[n + 6]});
  std::sort(out.begin(), out.end(), [](const dem::Contact& a, const dem::Contact& b) {
    return std::tie(a.id_i, a.id_j, a.point.x, a.point.z) <
           std::tie(b.id_i, b.id_j, b.point.x, b.point.z);
  });
  return out;
}

namespace {

// The active contacts binned on a grid of square buckets: a particle is tested against the
// contacts of its bucket only. A band (|along| < 2h, |across| <= h) lies within sqrt(5) h / |n|
// of the contact point, so every contact is listed in each bucket its disc of that radius
// touches; contacts with n = 0 (every particle in the band) are tested everywhere.
struct ContactBins {
  Vec2 lo;
  double size = 1.0;
  int nx = 0, nz = 0;
  std::vector<std::vector<std::size_t>> bins;
  std::vector<std::size_t> everywhere;

  ContactBins(const std::vector<dem::Contact>& contacts, double h) {
    std::vector<std::pair<std::size_t, double>> active;  // contact, reach
    Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      if (!(contacts[c].delta > 0.0)) continue;
      const double n = std::sqrt(core::norm2(contacts[c].normal));
      if (!(n > 0.0)) {
        everywhere.push_back(c);
        continue;
      }
      const double reach = 2.25 * h / n;  // > sqrt(5) h / |n|
      active.emplace_back(c, reach);
      const Vec2 p = contacts[c].point;
      lo = {std::min(lo.x, p.x - reach), std::min(lo.z, p.z - reach)};
      hi = {std::max(hi.x, p.x + reach), std::max(hi.z, p.z + reach)};
    }
    if (active.empty()) return;
    size = 4.5 * h;
    nx = static_cast<int>(std::min(4096.0, (hi.x - lo.x) / size)) + 1;
    nz = static_cast<int>(std::min(4096.0, (hi.z - lo.z) / size)) + 1;
    size = std::max({size, (hi.x - lo.x) / nx, (hi.z - lo.z) / nz});
    bins.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz), {});
    for (const auto& [c, reach] : active) {
      const Vec2 p = contacts[c].point;
      const int i0 = bin(p.x - reach, lo.x, nx), i1 = bin(p.x + reach, lo.x, nx);
      const int k0 = bin(p.z - reach, lo.z, nz), k1 = bin(p.z + reach, lo.z, nz);
      for (int k = k0; k <= k1; ++k)
        for (int i = i0; i <= i1; ++i) bins[static_cast<std::size_t>(k) * nx + i].push_back(c);
    }
  }
  int bin(double x, double x0, int n) const {
    return std::clamp(static_cast<int>(std::floor((x - x0) / size)), 0, n - 1);
  }
  /// The contacts whose band may hold p (none when p is outside every disc's bucket).
  const std::vector<std::size_t>* near(Vec2 p) const {
    if (bins.empty() || !(p.x >= lo.x && p.z >= lo.z)) return nullptr;
    const double fi = (p.x - lo.x) / size, fk = (p.z - lo.z) / size;
    if (!(fi < nx && fk < nz)) return nullptr;
    return &bins[static_cast<std::size_t>(fk) * nx + static_cast<std::size_t>(fi)];
  }
};

}  // namespace

long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta) {
  if (contacts.empty() || beta >= 1.0) return 0;
  long long damped = 0;
  const double half_length = 2.0 * h;  // the band is 4h long
  const ContactBins bins(contacts, h);
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    const Vec2 p{ps.x[n], ps.z[n]};
    double C = 1.0;
    const auto band = [&](const dem::Contact& c) {
      const Vec2 dp = p - c.point;
      const double along = std::abs(core::dot(dp, core::perp(c.normal)));
      const double across = std::abs(core::dot(dp, c.normal));
      if (along >= half_length || across > h) return;
      // eq. 20: C falls linearly from 1 at the band's ends to beta at the contact point
      C = std::min(C, beta + (1.0 - beta) * along / half_length);
    };
    if (const auto* near = bins.near(p))
      for (std::size_t c : *near) band(contacts[c]);
    for (std::size_t c : bins.everywhere) band(contacts[c]);
    if (C < 1.0) {
      ps.u[n] *= C, ps.w[n] *= C;
      ps.cxx[n] *= C, ps.cxz[n] *= C, ps.czx[n] *= C, ps.czz[n] *= C;
      ++damped;
    }
  }
  return damped;
}

}  // namespace picdem::coupling

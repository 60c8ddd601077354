#include "rebalance.hpp"

#include <utility>

#include "picdem/core/timer.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

std::vector<long long> cell_work(const grid::Decomposition& d, const particles::ParticleSet& ps) {
  const auto& spec = d.spec();
  const core::IndexBox own = d.owned_cells();
  std::vector<long long> count(static_cast<std::size_t>(own.size()), 0);
  for (std::size_t n = 0; n < ps.size(); ++n) {
    int i, k;
    spec.cell_of({ps.x[n], ps.z[n]}, i, k);
    if (own.contains(i, k))
      ++count[static_cast<std::size_t>(k - own.k0) * static_cast<std::size_t>(own.nx()) +
              static_cast<std::size_t>(i - own.i0)];
  }
  for (auto& c : count) c = kWorkCell + (c > 0 ? kWorkFluid : 0) + kWorkParticle * c;
  return count;
}

std::vector<core::Box2> rank_regions(const grid::Decomposition& d) {
  std::vector<core::Box2> out;
  const auto& s = d.spec();
  for (int r = 0; r < d.size(); ++r) {
    const auto b = d.owned_cells(r);
    out.push_back({{s.origin.x + b.i0 * s.h, s.origin.z + b.k0 * s.h},
                   {s.origin.x + b.i1 * s.h, s.origin.z + b.k1 * s.h}});
  }
  return out;
}

void move_to_cuts(const MovableState& s, const grid::Cuts& cuts) {
  core::ScopedTimer timer("rebalance: move");
  const grid::Decomposition from = s.d;
  s.d.set_cuts(cuts.xs, cuts.zs);
  s.halo = std::make_unique<grid::Halo>(s.d);
  if (s.fluid) *s.fluid = fluid::redistributed(*s.fluid, from, s.d);
  particles::migrate(s.particles, s.d);
  if (s.dem) s.dem->set_regions(rank_regions(s.d));
}

}  // namespace picdem::coupling

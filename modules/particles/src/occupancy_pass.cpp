#include "picdem/particles/occupancy_pass.hpp"

#include "picdem/particles/occupancy.hpp"

namespace picdem::particles {

void OccupancyPass::update(const ParticleSet& ps, const grid::Decomposition& d,
                           const grid::Halo& halo, const ParticleConfig& config, bool with_sums) {
  if (current) return;
  const int per_cell = config.per_cell_1d * config.per_cell_1d;
  if (S.data().empty()) S = grid::CellField(d, grid::Stagger::Cell, 0.0);
  if (count.data().empty()) count = grid::GridArray<int>(d, grid::Stagger::Cell, 0);
  if (with_sums)
    occupancy(ps, d, halo, per_cell, S, count, config, sums);
  else
    occupancy(ps, d, halo, per_cell, S, &count);
  current = true;
  sums_current = with_sums;
}

std::vector<long long> cell_work(const grid::Decomposition& d, const ParticleSet& ps) {
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

}  // namespace picdem::particles

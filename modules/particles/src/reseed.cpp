#include <algorithm>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/particles/motion.hpp"
#include "picdem/particles/transfer.hpp"
#include "stencil.hpp"

namespace picdem::particles {

namespace {

constexpr auto kAir = static_cast<signed char>(grid::CellState::Air);
constexpr auto kFluid = static_cast<signed char>(grid::CellState::Fluid);

/// A fluid cell whose four neighbours are not air (walls count as not air): adding particles
/// there does not move the free surface.
bool interior_fluid(const grid::GridArray<signed char>& state, const grid::GridSpec& s, int i,
                    int k) {
  if (state(i, k) != kFluid) return false;
  const int di[4] = {-1, 1, 0, 0}, dk[4] = {0, 0, -1, 1};
  for (int n = 0; n < 4; ++n) {
    const int a = i + di[n], b = k + dk[n];
    if (a < 0 || a >= s.nx || b < 0 || b >= s.nz) continue;
    if (state(a, b) == kAir) return false;
  }
  return true;
}

}  // namespace

bool reseed_changes(const ParticleConfig& config, const grid::Decomposition& d,
                    const grid::GridArray<int>& count,
                    const grid::GridArray<signed char>& cell_state) {
  if (config.min_per_cell == 0) return false;  // reseeding off: the particles are conserved
  const grid::GridSpec& s = d.spec();
  const core::IndexBox cells = d.owned_cells();
  for (int k = cells.k0; k < cells.k1; ++k)
    for (int i = cells.i0; i < cells.i1; ++i)
      if (count(i, k) > config.max_per_cell ||
          (count(i, k) < config.min_per_cell && interior_fluid(cell_state, s, i, k)))
        return true;
  return false;
}

void reseed(ParticleSet& p, const ParticleConfig& config, const grid::Decomposition& d,
            const grid::GridArray<int>& count, const grid::GridArray<signed char>& cell_state,
            const grid::FaceField& u, const grid::FaceField& w, long long step,
            const std::function<bool(core::Vec2)>& reject) {
  core::ScopedTimer timer("particles: reseed");
  if (config.min_per_cell == 0) return;  // reseeding off: no particle added or removed
  const grid::GridSpec& s = d.spec();
  const core::IndexBox cells = d.owned_cells();
  if (step < 0) throw core::SolverError("reseed: step must be >= 0, got " + std::to_string(step));
  // particles of each owned cell, as a list per cell
  const auto local = [&](int i, int k) {
    return static_cast<std::size_t>(k - cells.k0) * static_cast<std::size_t>(cells.nx()) +
           static_cast<std::size_t>(i - cells.i0);
  };
  std::vector<std::size_t> start(static_cast<std::size_t>(cells.size()) + 1, 0);
  std::vector<std::size_t> cell(p.size());
  for (std::size_t n = 0; n < p.size(); ++n) {
    int i, k;
    detail::cell_of(s, p.x[n], p.z[n], i, k);
    i = std::clamp(i, 0, s.nx - 1);
    k = std::clamp(k, 0, s.nz - 1);
    if (!cells.contains(i, k)) {
      std::ostringstream m;
      m << "reseed: particle " << p.id[n] << " at (" << p.x[n] << ", " << p.z[n]
        << ") is not in an owned cell; call migrate first";
      throw core::SolverError(m.str());
    }
    cell[n] = local(i, k);
    ++start[cell[n] + 1];
  }
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  std::vector<std::size_t> members(p.size());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t n = 0; n < p.size(); ++n) members[fill[cell[n]]++] = n;
  }

  const std::int64_t id0 = first_reseed_id(s, config);
  const auto cells_total = static_cast<std::int64_t>(s.nx) * s.nz;
  // a seed of its own, so that reseeded positions never repeat the initial ones
  const std::uint64_t reseed_seed = core::hash_counters(config.seed, 0x7265736565640000ULL);
  std::vector<char> keep(p.size(), 1);
  ParticleSet added;
  added.spec = s;
  for (int k = cells.k0; k < cells.k1; ++k)
    for (int i = cells.i0; i < cells.i1; ++i) {
      const std::size_t c = local(i, k);
      const int n_c = static_cast<int>(start[c + 1] - start[c]);
      if (count(i, k) != n_c) {
        std::ostringstream m;
        m << "reseed: count(" << i << ", " << k << ") = " << count(i, k) << " but the cell holds "
          << n_c << " particles; call count_per_cell after migrate";
        throw core::SolverError(m.str());
      }
      if (n_c > config.max_per_cell) {
        // remove the surplus with the largest ids: a choice independent of particle order
        auto first = members.begin() + static_cast<std::ptrdiff_t>(start[c]);
        auto last = members.begin() + static_cast<std::ptrdiff_t>(start[c + 1]);
        std::sort(first, last, [&](std::size_t a, std::size_t b) { return p.id[a] > p.id[b]; });
        for (int m = 0; m < n_c - config.max_per_cell; ++m) keep[*(first + m)] = 0;
      } else if (n_c < config.min_per_cell && interior_fluid(cell_state, s, i, k)) {
        const int need = config.min_per_cell - n_c;
        const auto gid = static_cast<std::uint64_t>(s.cell_gid(i, k));
        int made = 0;
        for (int attempt = 0; attempt < 8 * need && made < need; ++attempt) {
          const auto a = static_cast<std::uint64_t>(attempt);
          const core::Vec2 pos{
              s.origin.x +
                  (i + core::uniform01(reseed_seed, gid, static_cast<std::uint64_t>(step), 2 * a)) *
                      s.h,
              s.origin.z + (k + core::uniform01(reseed_seed, gid, static_cast<std::uint64_t>(step),
                                                2 * a + 1)) *
                               s.h};
          if (reject && reject(pos)) continue;
          double c4[4] = {0.0, 0.0, 0.0, 0.0};
          const core::Vec2 vel = config.transfer == TransferScheme::Apic
                                     ? sample_with_gradient(u, w, s, pos, c4)
                                     : sample(u, w, s, pos);
          // id = first_reseed_id + (step cells + gid) max_per_cell + n
          const std::int64_t new_id =
              id0 + (step * cells_total + static_cast<std::int64_t>(gid)) * config.max_per_cell +
              made;
          added.push_back(new_id, pos, vel, c4);
          ++made;
        }
      }
    }
  p.keep_if(keep);
  p.reserve(p.size() + added.size());
  for (std::size_t n = 0; n < added.size(); ++n) p.push_back_from(added, n);
}

}  // namespace picdem::particles

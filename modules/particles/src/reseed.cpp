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

namespace {

/// The particles of each owned cell as one list per cell: cell c (row-major over the owned
/// box) holds members[start[c]] .. members[start[c + 1] - 1], in particle order.
struct CellLists {
  std::vector<std::size_t> start, members;
  /// number of particles in cell c
  int size(std::size_t c) const { return static_cast<int>(start[c + 1] - start[c]); }
};

/// Index of owned cell (i, k) in the lists.
std::size_t local_cell(const core::IndexBox& cells, int i, int k) {
  return static_cast<std::size_t>(k - cells.k0) * static_cast<std::size_t>(cells.nx()) +
         static_cast<std::size_t>(i - cells.i0);
}

/// Sorts the particles into their owned cells (a counting sort); a particle outside them throws.
CellLists particles_by_cell(const ParticleSet& p, const grid::GridSpec& s,
                            const core::IndexBox& cells) {
  CellLists lists;
  lists.start.assign(static_cast<std::size_t>(cells.size()) + 1, 0);
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
    cell[n] = local_cell(cells, i, k);
    ++lists.start[cell[n] + 1];
  }
  for (std::size_t c = 0; c + 1 < lists.start.size(); ++c) lists.start[c + 1] += lists.start[c];
  lists.members.resize(p.size());
  std::vector<std::size_t> fill(lists.start.begin(), lists.start.end() - 1);
  for (std::size_t n = 0; n < p.size(); ++n) lists.members[fill[cell[n]]++] = n;
  return lists;
}

/// Throws unless `count` holds the number of particles of every owned cell.
void check_count(const grid::GridArray<int>& count, const CellLists& lists,
                 const core::IndexBox& cells) {
  for (int k = cells.k0; k < cells.k1; ++k)
    for (int i = cells.i0; i < cells.i1; ++i) {
      const int n_c = lists.size(local_cell(cells, i, k));
      if (count(i, k) == n_c) continue;
      std::ostringstream m;
      m << "reseed: count(" << i << ", " << k << ") = " << count(i, k) << " but the cell holds "
        << n_c << " particles; call count_per_cell after migrate";
      throw core::SolverError(m.str());
    }
}

/// Marks for removal the particles of cell c beyond max_per_cell, those with the largest ids:
/// a choice independent of particle order.
void mark_surplus(const ParticleSet& p, CellLists& lists, std::size_t c, int max_per_cell,
                  std::vector<char>& keep) {
  auto first = lists.members.begin() + static_cast<std::ptrdiff_t>(lists.start[c]);
  auto last = lists.members.begin() + static_cast<std::ptrdiff_t>(lists.start[c + 1]);
  std::sort(first, last, [&](std::size_t a, std::size_t b) { return p.id[a] > p.id[b]; });
  for (int m = 0; m < lists.size(c) - max_per_cell; ++m) keep[*(first + m)] = 0;
}

/// Makes the particles a cell lacks: positions, ids and velocities depend on the cell and the
/// step alone, not on the rank or the particle order.
class NewParticles {
 public:
  NewParticles(const ParticleConfig& config, const grid::GridSpec& spec, const grid::FaceField& u,
               const grid::FaceField& w, const std::function<bool(core::Vec2)>& reject,
               long long step)
      : config_(config),
        spec_(spec),
        u_(u),
        w_(w),
        reject_(reject),
        step_(step),
        id0_(first_reseed_id(spec, config)),
        cells_total_(static_cast<std::int64_t>(spec.nx) * spec.nz),
        // a seed of its own, so that reseeded positions never repeat the initial ones
        seed_(core::hash_counters(config.seed, 0x7265736565640000ULL)) {}

  /// Adds up to `need` particles to cell (i, k) at random positions that `reject` accepts, with
  /// the grid velocity there (and its gradient under APIC); at most 8 need attempts.
  void fill_cell(int i, int k, int need, ParticleSet& added) const {
    const grid::GridSpec& s = spec_;
    const auto gid = static_cast<std::uint64_t>(s.cell_gid(i, k));
    const auto step = static_cast<std::uint64_t>(step_);
    int made = 0;
    for (int attempt = 0; attempt < 8 * need && made < need; ++attempt) {
      const auto a = static_cast<std::uint64_t>(attempt);
      const double fx = core::uniform01(seed_, gid, step, 2 * a);
      const double fz = core::uniform01(seed_, gid, step, 2 * a + 1);
      const core::Vec2 pos{s.origin.x + (i + fx) * s.h, s.origin.z + (k + fz) * s.h};
      if (reject_ && reject_(pos)) continue;
      double c4[4] = {0.0, 0.0, 0.0, 0.0};
      const core::Vec2 vel = config_.transfer == TransferScheme::Apic
                                 ? sample_with_gradient(u_, w_, s, pos, c4)
                                 : sample(u_, w_, s, pos);
      // id = first_reseed_id + (step cells + gid) max_per_cell + n
      const std::int64_t new_id =
          id0_ + (step_ * cells_total_ + static_cast<std::int64_t>(gid)) * config_.max_per_cell +
          made;
      added.push_back(new_id, pos, vel, c4);
      ++made;
    }
  }

 private:
  const ParticleConfig& config_;
  const grid::GridSpec& spec_;
  const grid::FaceField& u_;
  const grid::FaceField& w_;
  const std::function<bool(core::Vec2)>& reject_;
  const std::int64_t step_;
  const std::int64_t id0_;          ///< first_reseed_id
  const std::int64_t cells_total_;  ///< nx nz
  const std::uint64_t seed_;        ///< reseeding's own random seed
};

}  // namespace

void reseed(ParticleSet& p, const ParticleConfig& config, const grid::Decomposition& d,
            const grid::GridArray<int>& count, const grid::GridArray<signed char>& cell_state,
            const grid::FaceField& u, const grid::FaceField& w, long long step,
            const std::function<bool(core::Vec2)>& reject) {
  core::ScopedTimer timer("particles: reseed");
  if (config.min_per_cell == 0) return;  // reseeding off: no particle added or removed
  const grid::GridSpec& s = d.spec();
  const core::IndexBox cells = d.owned_cells();
  if (step < 0) throw core::SolverError("reseed: step must be >= 0, got " + std::to_string(step));
  CellLists lists = particles_by_cell(p, s, cells);
  check_count(count, lists, cells);
  const NewParticles new_particles(config, s, u, w, reject, step);
  std::vector<char> keep(p.size(), 1);
  ParticleSet added;
  added.spec = s;
  for (int k = cells.k0; k < cells.k1; ++k)
    for (int i = cells.i0; i < cells.i1; ++i) {
      const std::size_t c = local_cell(cells, i, k);
      const int n_c = lists.size(c);
      if (n_c > config.max_per_cell)
        mark_surplus(p, lists, c, config.max_per_cell, keep);
      else if (n_c < config.min_per_cell && interior_fluid(cell_state, s, i, k))
        new_particles.fill_cell(i, k, config.min_per_cell - n_c, added);
    }
  p.keep_if(keep);
  p.reserve(p.size() + added.size());
  for (std::size_t n = 0; n < added.size(); ++n) p.push_back_from(added, n);
}

}  // namespace picdem::particles

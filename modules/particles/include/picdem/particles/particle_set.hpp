#pragma once
// Fluid marker particles: their configuration (case-file keys), their storage (structure of
// arrays, owned by the rank that owns their cell) and their initial seeding.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::particles {

enum class TransferScheme { Flip, Apic };
enum class AdvectionScheme { Rk2, Rk3 };

/// Particle settings, read once from the validated case.
struct ParticleConfig {
  int per_cell_1d = 2;     ///< particles per cell along each axis at seeding
  double jitter = 0.5;     ///< random offset, as a share of the sub-cell spacing
  int min_per_cell = 2;    ///< reseeding adds particles below this in interior fluid cells
  int max_per_cell = 8;    ///< reseeding removes particles above this
  std::uint64_t seed = 1;  ///< seed of the counter-based random numbers
  TransferScheme transfer = TransferScheme::Flip;
  double flip_ratio = 0.95;  ///< share of FLIP in the FLIP/PIC blend (0: PIC)
  AdvectionScheme advection = AdvectionScheme::Rk2;
};

/// Declares particles/*, transfer/scheme, transfer/flip_ratio and advection/scheme.
void declare_parameters(core::ParamSchema& schema);
ParticleConfig config_from(const core::Params& params);

/// Ghost width the particle stencils need: P2G and G2P reach one face beyond the particle's
/// cell; advection samples the grid up to two cells away from the owned block (|v| dt <= 2 h).
int required_halo(const ParticleConfig& config);

/// The particles this rank owns (those in its owned cells), as a structure of arrays.
/// Every particle has unit mass: grid weights count particles.
struct ParticleSet {
  std::vector<double> x, z, u, w;
  std::vector<double> cxx, cxz, czx, czz;  ///< APIC affine matrix C = grad v, zero under FLIP/PIC
  std::vector<std::int64_t> id;            ///< global ids, unique over ranks and over the run
  grid::GridSpec spec;                     ///< the grid the positions live on (set by seed)

  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }
  void clear();
  void reserve(std::size_t n);
  void resize(std::size_t n);
  /// Appends particle `n` of `other`.
  void push_back_from(const ParticleSet& other, std::size_t n);
  /// Appends a particle with position, velocity and C (cxx, cxz, czx, czz).
  void push_back(std::int64_t gid, core::Vec2 p, core::Vec2 v, const double (&c)[4]);
  /// Keeps the particles whose keep[n] is true, in their order.
  void keep_if(const std::vector<char>& keep);
  /// Reorders the particles: particle n takes the place of particle order[n].
  void permute(const std::vector<std::size_t>& order);
  /// Multiplies the velocity and C of every particle whose factor(position) is below 1 by that
  /// factor (the gap damping of eq. 20, coupling::damp_gap_particles); returns how many.
  long long scale_velocities(const std::function<double(core::Vec2)>& factor);

  /// The arrays a checkpoint keeps (everything but `spec`), in one place: f(name, array) for
  /// x, z, u, w, cxx, cxz, czx, czz (double) and id (int64), in this order. The order of the
  /// particles is part of the state: it fixes the order of the sums in P2G.
  template <class F>
  void for_each_saved(F&& f) {
    visit_saved(*this, f);
  }
  template <class F>
  void for_each_saved(F&& f) const {
    visit_saved(*this, f);
  }

 private:
  template <class Set, class F>
  static void visit_saved(Set& s, F& f) {
    f("x", s.x), f("z", s.z), f("u", s.u), f("w", s.w);
    f("cxx", s.cxx), f("cxz", s.cxz), f("czx", s.czx), f("czz", s.czz);
    f("id", s.id);
  }
};

/// Sum of the particles' velocities over all ranks (collective): their momentum per unit
/// particle mass.
core::Vec2 velocity_sum(const ParticleSet& particles, const core::Comm& comm);

/// Seeds per_cell_1d^2 jittered particles at rest in every owned cell whose centre satisfies
/// inside(centre). Positions and ids depend on the cell's global id only: the union over ranks
/// is the same whatever the rank count. Ids are cell_gid * per_cell_1d^2 + n.
///
/// The jitter keeps, over the particles of each dual cell (the square between four cell
/// centres), the sums of x, z and x z of the lattice, so the occupancy's bilinear tent reads the
/// seeding exactly as the lattice (picdem/particles/occupancy.hpp): jitter moves no free
/// surface. Particles whose lattice position fails `keep` (if given) are left on the lattice and
/// out of their dual cell's sums: the caller removes them (water outside the case's region, in
/// bodies). On a cell's centre line (odd per_cell_1d) a particle is not jittered across it.
ParticleSet seed(const grid::Decomposition& decomposition, const ParticleConfig& config,
                 const std::function<bool(core::Vec2)>& inside,
                 const std::function<bool(core::Vec2)>& keep = nullptr);

/// First id handed out by reseeding: no seeded particle reaches it.
std::int64_t first_reseed_id(const grid::GridSpec& spec, const ParticleConfig& config);

/// Sorts the particles by cell (row-major cell gid), and by id within a cell: the order is a
/// function of the set alone, and P2G / G2P walk the grid in memory order.
void sort_by_cell(ParticleSet& particles, const grid::GridSpec& spec);

}  // namespace picdem::particles

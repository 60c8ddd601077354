#pragma once
// Where the fluid is at t = 0: the case's `water` family (blocks and still-water levels, their
// union), declared with its checks against the tank, read once, and seeded.
#include <functional>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles {

/// Declares the `water` family (variants box and level) and checks that each entry lies in the
/// tank (grid/origin, grid/length, grid/height).
void declare_water_parameters(core::ParamSchema& schema);

/// The water regions of a validated case, read once: seeding tests every candidate point
/// against them (five per cell), and looking them up in the parameter list for each point cost
/// more than the first ten steps of the 6-layer case (doc/performance.md).
class WaterRegions {
 public:
  explicit WaterRegions(const core::Params& params);
  /// Whether x is in a block (edges included) or at or below a level.
  bool contains(core::Vec2 x) const;

 private:
  struct Region {
    bool box = false;  ///< a block; else everything below the level z1
    double x0 = 0, x1 = 0, z0 = 0, z1 = 0;
  };
  std::vector<Region> regions_;
};

/// The water at t = 0 (particles::seed): cells are seeded whose centre or a corner is in the
/// water, and particles outside it or inside a body (`in_body`, may be null) are removed, so
/// that cut cells whose centre is covered still get particles in their fluid part. The seeding's
/// jitter keeps the lattice's occupancy over the particles whose lattice position is wet: a
/// level surface on a cell face is seeded flat.
ParticleSet seed_water(const grid::Decomposition& decomposition, const ParticleConfig& config,
                       const WaterRegions& water, const std::function<bool(core::Vec2)>& in_body);

}  // namespace picdem::particles

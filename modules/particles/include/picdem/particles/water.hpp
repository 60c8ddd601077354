#pragma once
// Where the fluid is at t = 0: the case's `water` family (blocks and still-water levels, their
// union), declared with its checks against the tank, and read once for seeding.
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"

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

}  // namespace picdem::particles

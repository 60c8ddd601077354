#pragma once
// The plain structs through which the fluid and the solid solver meet (they never include each
// other). Per unit depth: mass = density x area, inertia = density x polar second moment about the
// centre of mass.
#include <cstdint>

#include "picdem/core/vec2.hpp"

namespace picdem::core {

/// Kinematic state of one rigid solid.
struct SolidState {
  std::int64_t id = 0;   ///< global id, stable over the run
  Vec2 x;                ///< centre of mass
  double theta = 0.0;    ///< rotation angle (counter-clockwise, rad)
  Vec2 v;                ///< velocity of the centre of mass
  double omega = 0.0;    ///< angular velocity (counter-clockwise, rad/s)
  double mass = 0.0;     ///< per unit depth, kg/m
  double inertia = 0.0;  ///< per unit depth about the centre of mass, kg m
  int shape = 0;         ///< index into the shape table
};

/// External loads on one solid over a step.
struct SolidLoads {
  std::int64_t id = 0;
  Vec2 force;
  double torque = 0.0;
};

}  // namespace picdem::core

#pragma once
// The solids and obstacles of a scene as the implicit viscous operator sees them
// (fluid::ViscousBody: inside test, rigid velocity, centre, area); doc/viscous.md.
#include <vector>

#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::coupling {

/// The scene's solids (shape contains at the pose, velocity and angular velocity of their
/// state, centre of mass, area), then its obstacles (even-odd point in polygon, at rest).
std::vector<fluid::ViscousBody> viscous_bodies(const SolidScene& scene);

}  // namespace picdem::coupling

#include "picdem/coupling/solids_in_fluid.hpp"

#include "picdem/dem/gap_damping.hpp"

namespace picdem::coupling {

long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta) {
  if (contacts.empty() || beta >= 1.0) return 0;
  const dem::GapDamping gap(contacts, h, beta);
  return ps.scale_velocities([&](core::Vec2 x) { return gap.factor(x); });  // eq. 20
}

}  // namespace picdem::coupling

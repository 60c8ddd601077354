#include "picdem/coupling/solids_in_fluid.hpp"

#include "picdem/dem/gap_damping.hpp"

namespace picdem::coupling {

long long damp_gap_particles(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts,
                             double h, double beta) {
  if (contacts.empty() || beta >= 1.0) return 0;
  long long damped = 0;
  const dem::GapDamping gap(contacts, h, beta);
  for (std::size_t n = 0; n < ps.x.size(); ++n) {
    const double C = gap.factor({ps.x[n], ps.z[n]});  // eq. 20
    if (C < 1.0) {
      ps.u[n] *= C, ps.w[n] *= C;
      ps.cxx[n] *= C, ps.cxz[n] *= C, ps.czx[n] *= C, ps.czz[n] *= C;
      ++damped;
    }
  }
  return damped;
}

}  // namespace picdem::coupling

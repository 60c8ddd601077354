#pragma once
// The contacts as the fluid sees them: every rank's active contacts gathered, and eq. 20's damping
// factor C of the fluid trapped in a contact's gap (METHOD.md section 6; doc/coupling.md, "Gap
// damping"). The particles' velocities are scaled by the caller (coupling::damp_gap_particles).
#include <cstddef>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/dem/dem_solver.hpp"

namespace picdem::dem {

/// Collective: every rank's active contacts, on every rank, in a fixed order.
std::vector<Contact> all_contacts(const DemSolver& dem, const core::Comm& comm);

/// Eq. 20: a point in the band of an active contact (4h along the tangent, centred at the contact
/// point, h either side of it along the normal) has the factor C, linear from 1 at the band's ends
/// to beta at the contact point; where bands overlap the smallest C; 1 outside every band. The
/// contacts are binned on a grid of square buckets: a point is tested against the contacts of its
/// bucket only (the same C, bit for bit, as testing every contact).
class GapDamping {
 public:
  /// `contacts` must outlive this.
  GapDamping(const std::vector<Contact>& contacts, double h, double beta);
  double factor(core::Vec2 p) const;

 private:
  int bin(double x, double x0, int n) const;
  const std::vector<Contact>& contacts_;
  double h_, beta_;
  core::Vec2 lo_;
  double size_ = 1.0;
  int nx_ = 0, nz_ = 0;
  std::vector<std::vector<std::size_t>> bins_;
  std::vector<std::size_t> everywhere_;  ///< contacts with n = 0: every point in the band
};

}  // namespace picdem::dem

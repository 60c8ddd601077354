// SolidCoupling lists joined over ranks, and the pressure loads J_s p on the solids (eq. 6) from
// the rows the solver kept (RigidBodyTerm::loads).
#include "solid_couplings.hpp"

#include <sstream>

#include "picdem/core/error.hpp"

namespace picdem::fluid::detail {

std::map<std::int64_t, SolidCoupling> gather_couplings(const std::vector<SolidCoupling>& mine,
                                                       const core::Comm& comm) {
  // Packed as [id, n, m, I, V*0, V*1, V*2, F0, F1, F2, (cell, a0, a1, a2) x n] per solid.
  std::vector<double> buf;
  for (const auto& s : mine) {
    if (s.cells.size() != s.a.size()) {
      std::ostringstream m;
      m << "SolidCoupling of solid " << s.id << " has " << s.cells.size() << " cells but "
        << s.a.size() << " vectors a; they must match";
      throw core::InputError(m.str());
    }
    buf.insert(buf.end(),
               {static_cast<double>(s.id), static_cast<double>(s.cells.size()), s.mass, s.inertia,
                s.v_star[0], s.v_star[1], s.v_star[2], s.load[0], s.load[1], s.load[2]});
    for (std::size_t n = 0; n < s.cells.size(); ++n)
      buf.insert(buf.end(), {static_cast<double>(s.cells[n]), s.a[n][0], s.a[n][1], s.a[n][2]});
  }
  const std::vector<double> all = comm.size() > 1 ? comm.all_gather(buf) : buf;
  std::map<std::int64_t, SolidCoupling> joined;
  for (std::size_t p = 0; p < all.size();) {
    const auto id = static_cast<std::int64_t>(all[p]);
    const auto n = static_cast<std::size_t>(all[p + 1]);
    SolidCoupling& s = joined[id];
    s.id = id;
    s.mass = all[p + 2];
    s.inertia = all[p + 3];
    s.v_star = {all[p + 4], all[p + 5], all[p + 6]};
    for (std::size_t m = 0; m < 3; ++m) s.load[m] += all[p + 7 + m];
    p += 10;
    for (std::size_t c = 0; c < n; ++c, p += 4) {
      s.cells.push_back(static_cast<long long>(all[p]));
      s.a.push_back({all[p + 1], all[p + 2], all[p + 3]});
    }
  }
  for (const auto& [id, s] : joined)
    if (!(s.mass > 0.0) || !(s.inertia > 0.0)) {
      std::ostringstream m;
      m << "SolidCoupling of solid " << id << ": mass = " << s.mass << ", inertia = " << s.inertia
        << "; both must be > 0";
      throw core::InputError(m.str());
    }
  return joined;
}

std::vector<core::SolidLoads> coupling_loads(const std::map<std::int64_t, SolidCoupling>& joined,
                                             const grid::CellField& p,
                                             const grid::Decomposition& d) {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  std::vector<double> sums;
  sums.reserve(3 * joined.size());
  for (const auto& [id, s] : joined) {
    double f[3] = {0.0, 0.0, 0.0};
    for (std::size_t n = 0; n < s.cells.size(); ++n) {
      const long long c = s.cells[n];
      const int i = static_cast<int>(c % g.nx), k = static_cast<int>(c / g.nx);
      if (c < 0 || !own.contains(i, k)) continue;
      // J_s p = - sum_c a_{s,c} p_c  (eq. 6: force and torque of the pressure on the solid)
      for (std::size_t m = 0; m < 3; ++m) f[m] -= s.a[n][m] * p(i, k);
    }
    sums.insert(sums.end(), {f[0], f[1], f[2]});
  }
  d.comm().sum_in_place(sums);
  std::vector<core::SolidLoads> loads;
  std::size_t m = 0;
  for (const auto& [id, s] : joined) {
    core::SolidLoads l;
    l.id = id;
    l.force = {sums[m] + s.load[0], sums[m + 1] + s.load[1]};
    l.torque = sums[m + 2] + s.load[2];
    loads.push_back(l);
    m += 3;
  }
  return loads;
}

}  // namespace picdem::fluid::detail

#include "picdem/dem/gap_damping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

namespace picdem::dem {

using core::Vec2;

std::vector<Contact> all_contacts(const DemSolver& dem, const core::Comm& comm) {
  std::vector<double> mine;
  for (const auto& c : dem.active_contacts())
    mine.insert(mine.end(), {static_cast<double>(c.id_i), static_cast<double>(c.id_j), c.point.x,
                             c.point.z, c.normal.x, c.normal.z, c.delta});
  const auto all = comm.all_gather(mine);
  std::vector<Contact> out;
  for (std::size_t n = 0; n + 7 <= all.size(); n += 7)
    out.push_back({static_cast<std::int64_t>(all[n]),
                   static_cast<std::int64_t>(all[n + 1]),
                   {all[n + 2], all[n + 3]},
                   {all[n + 4], all[n + 5]},
                   all[n + 6]});
  std::sort(out.begin(), out.end(), [](const Contact& a, const Contact& b) {
    return std::tie(a.id_i, a.id_j, a.point.x, a.point.z) <
           std::tie(b.id_i, b.id_j, b.point.x, b.point.z);
  });
  return out;
}

// A band (|along| < 2h, |across| <= h) lies within sqrt(5) h / |n| of the contact point, so every
// contact is listed in each bucket its disc of that radius touches.
GapDamping::GapDamping(const std::vector<Contact>& contacts, double h, double beta)
    : contacts_(contacts), h_(h), beta_(beta) {
  std::vector<std::pair<std::size_t, double>> active;  // contact, reach
  Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  lo_ = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (!(contacts[c].delta > 0.0)) continue;
    const double n = std::sqrt(core::norm2(contacts[c].normal));
    if (!(n > 0.0)) {
      everywhere_.push_back(c);
      continue;
    }
    const double reach = 2.25 * h / n;  // > sqrt(5) h / |n|
    active.emplace_back(c, reach);
    const Vec2 p = contacts[c].point;
    lo_ = {std::min(lo_.x, p.x - reach), std::min(lo_.z, p.z - reach)};
    hi = {std::max(hi.x, p.x + reach), std::max(hi.z, p.z + reach)};
  }
  if (active.empty()) return;
  size_ = 4.5 * h;
  nx_ = static_cast<int>(std::min(4096.0, (hi.x - lo_.x) / size_)) + 1;
  nz_ = static_cast<int>(std::min(4096.0, (hi.z - lo_.z) / size_)) + 1;
  size_ = std::max({size_, (hi.x - lo_.x) / nx_, (hi.z - lo_.z) / nz_});
  bins_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(nz_), {});
  for (const auto& [c, reach] : active) {
    const Vec2 p = contacts[c].point;
    const int i0 = bin(p.x - reach, lo_.x, nx_), i1 = bin(p.x + reach, lo_.x, nx_);
    const int k0 = bin(p.z - reach, lo_.z, nz_), k1 = bin(p.z + reach, lo_.z, nz_);
    for (int k = k0; k <= k1; ++k)
      for (int i = i0; i <= i1; ++i) bins_[static_cast<std::size_t>(k) * nx_ + i].push_back(c);
  }
}

int GapDamping::bin(double x, double x0, int n) const {
  return std::clamp(static_cast<int>(std::floor((x - x0) / size_)), 0, n - 1);
}

double GapDamping::factor(Vec2 p) const {
  const double half_length = 2.0 * h_;  // the band is 4h long
  double C = 1.0;
  const auto band = [&](const Contact& c) {
    const Vec2 dp = p - c.point;
    const double along = std::abs(core::dot(dp, core::perp(c.normal)));
    const double across = std::abs(core::dot(dp, c.normal));
    if (along >= half_length || across > h_) return;
    // eq. 20: C falls linearly from 1 at the band's ends to beta at the contact point
    C = std::min(C, beta_ + (1.0 - beta_) * along / half_length);
  };
  // The contacts of p's bucket (none when p is outside every disc's bucket).
  if (!bins_.empty() && p.x >= lo_.x && p.z >= lo_.z) {
    const double fi = (p.x - lo_.x) / size_, fk = (p.z - lo_.z) / size_;
    if (fi < nx_ && fk < nz_)
      for (std::size_t c : bins_[static_cast<std::size_t>(fk) * nx_ + static_cast<std::size_t>(fi)])
        band(contacts_[c]);
  }
  for (std::size_t c : everywhere_) band(contacts_[c]);
  return C;
}

}  // namespace picdem::dem

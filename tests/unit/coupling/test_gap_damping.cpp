// Eq. 20's gap damping (damp_gap_particles) against a direct evaluation over every contact for
// every particle: the contacts are binned for speed, and the binning must change no particle's
// velocity, not even in the last bit (bands of active and inactive contacts, overlapping bands,
// non-unit normals, particles on and around the band edges).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "picdem/coupling/solids_in_fluid.hpp"

using namespace picdem;

namespace {

// Eq. 20 evaluated directly: every contact for every particle.
void damp_directly(particles::ParticleSet& ps, const std::vector<dem::Contact>& contacts, double h,
                   double beta) {
  for (std::size_t n = 0; n < ps.size(); ++n) {
    double C = 1.0;
    for (const auto& c : contacts) {
      if (!(c.delta > 0.0)) continue;
      const core::Vec2 dp = core::Vec2{ps.x[n], ps.z[n]} - c.point;
      const double along = std::abs(core::dot(dp, core::perp(c.normal)));
      const double across = std::abs(core::dot(dp, c.normal));
      if (along >= 2.0 * h || across > h) continue;
      C = std::min(C, beta + (1.0 - beta) * along / (2.0 * h));
    }
    if (C < 1.0)
      for (auto* v : {&ps.u, &ps.w, &ps.cxx, &ps.cxz, &ps.czx, &ps.czz}) (*v)[n] *= C;
  }
}

}  // namespace

TEST(GapDamping, BinnedEqualsDirectBitwise) {
  const double h = 0.01, beta = 0.2;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> in_tank(0.0, 1.0), angle(0.0, 6.283185307179586);
  std::vector<dem::Contact> contacts;
  for (int c = 0; c < 40; ++c) {
    const double a = angle(rng), scale = c % 7 == 0 ? 1.3 : 1.0;  // a few non-unit normals
    contacts.push_back({c,
                        c + 1,
                        {in_tank(rng), in_tank(rng)},
                        {scale * std::cos(a), scale * std::sin(a)},
                        c % 5 == 0 ? -1e-4 : 1e-4});
  }
  contacts.push_back({50, 51, {0.5, 0.5}, {1.0, 0.0}, 1e-4});  // two bands crossing at (0.5, 0.5)
  contacts.push_back({52, 53, {0.5, 0.5}, {0.0, 1.0}, 1e-4});
  particles::ParticleSet ps;
  const double c4[4] = {0.3, -0.2, 0.1, 0.4};
  for (int n = 0; n < 20000; ++n)
    ps.push_back(n, {in_tank(rng), in_tank(rng)}, {1.0 + in_tank(rng), -in_tank(rng)}, c4);
  for (int n = 0; n < 400; ++n) {  // on a lattice around the crossing, edges included
    const double x = 0.5 + (n % 20 - 10) * 0.25 * h, z = 0.5 + (n / 20 - 10) * 0.25 * h;
    ps.push_back(20000 + n, {x, z}, {1.0, 1.0}, c4);
  }
  particles::ParticleSet expect = ps;
  damp_directly(expect, contacts, h, beta);
  const long long damped = coupling::damp_gap_particles(ps, contacts, h, beta);
  for (std::size_t n = 0; n < ps.size(); ++n) {
    ASSERT_EQ(ps.u[n], expect.u[n]) << n;
    ASSERT_EQ(ps.w[n], expect.w[n]) << n;
    ASSERT_EQ(ps.cxx[n], expect.cxx[n]) << n;
    ASSERT_EQ(ps.czz[n], expect.czz[n]) << n;
  }
  long long expect_damped = 0;
  for (std::size_t n = 0; n < ps.size(); ++n) expect_damped += expect.cxz[n] != -0.2;
  EXPECT_EQ(damped, expect_damped);
  EXPECT_GT(damped, 300);  // the test reaches the bands
}

// The half evaluation of the contact list (doc/dem.md, "Each pair evaluated once"): an owned pair
// is evaluated at the entry of its lower local index and read back at the other. Checked against
// an independent sum: every pair of a crowded scene of disks and turned squares solved alone (a
// solver holding only those two), its loads added to both solids. A wrong mirror entry gives one
// solid another pair's load, or none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dem_fixtures.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793;
const double h = 5e-4, rho = 2700.0;
const double L = 0.01;               // square side
const double r = L / std::sqrt(pi);  // disk of the square's area: every mass equal, so a
                                     // pair alone has the scene's coefficients

std::vector<core::SolidLoads> loads_of(const std::vector<SolidSpec>& solids) {
  return collision_loads(weightless(h), solids);
}

/// A jittered lattice whose spacing lets neighbours overlap their gaps; every other solid a
/// square at a random angle, ids shuffled against the positions; random velocities and spins so
/// that the dashpots and the tangential law act.
std::vector<SolidSpec> crowd(unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int nx = 7, nz = 6;
  std::vector<std::int64_t> ids(nx * nz);
  for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<std::int64_t>(k);
  std::shuffle(ids.begin(), ids.end(), gen);
  std::vector<SolidSpec> out;
  const double spacing = 2.0 * r + 1.2 * h;  // disks' gaps of 2h overlap by 0.8 h
  for (int k = 0; k < nz; ++k)
    for (int c = 0; c < nx; ++c) {
      const auto n = static_cast<std::size_t>(k * nx + c);
      const core::Vec2 x{0.3 + (c + 0.5 * (k % 2)) * spacing + 0.2 * h * u(gen),
                         0.3 + k * spacing * 0.87 + 0.2 * h * u(gen)};
      const core::Vec2 v{0.05 * u(gen), 0.05 * u(gen)};
      SolidSpec s = (n % 2 == 0) ? disk(ids[n], r, rho, x, v, 2.0 * u(gen))
                                 : square(ids[n], L, rho, x, pi * u(gen), v);
      s.state.omega = 2.0 * u(gen);
      out.push_back(s);
    }
  return out;
}
}  // namespace

TEST(HalfList, EveryPairsLoadsAsIfEvaluatedAlone) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto solids = crowd(seed);
    const auto all = loads_of(solids);
    ASSERT_EQ(all.size(), solids.size());
    // the reference: the sum over every pair solved alone
    std::vector<core::Vec2> F(solids.size());
    std::vector<double> M(solids.size(), 0.0);
    int pairs = 0;
    for (std::size_t a = 0; a < solids.size(); ++a)
      for (std::size_t b = a + 1; b < solids.size(); ++b) {
        const auto two = loads_of({solids[a], solids[b]});
        bool touching = false;
        for (const auto& l : two) {
          // loads come back ordered by id; map them to the scene's ids
          const std::size_t k = static_cast<std::size_t>(l.id);
          F[k] += l.force;
          M[k] += l.torque;
          touching = touching || core::norm2(l.force) > 0.0;
        }
        pairs += touching ? 1 : 0;
      }
    // enough contacts for every solid to have several (more than 3 on average), mirrored and
    // evaluated entries alike
    EXPECT_GT(2 * pairs, static_cast<int>(3 * solids.size())) << "seed " << seed;
    double Fmax = 0.0, Mmax = 0.0;
    for (std::size_t k = 0; k < F.size(); ++k) {
      Fmax = std::max(Fmax, core::norm(F[k]));
      Mmax = std::max(Mmax, std::abs(M[k]));
    }
    ASSERT_GT(Fmax, 0.0);
    for (const auto& l : all) {
      const auto k = static_cast<std::size_t>(l.id);
      // only the order of the sums differs from the reference
      EXPECT_NEAR(l.force.x, F[k].x, 1e-12 * Fmax) << "seed " << seed << " id " << l.id;
      EXPECT_NEAR(l.force.z, F[k].z, 1e-12 * Fmax) << "seed " << seed << " id " << l.id;
      EXPECT_NEAR(l.torque, M[k], 1e-12 * Mmax) << "seed " << seed << " id " << l.id;
    }
  }
}

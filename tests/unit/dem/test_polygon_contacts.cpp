// Polygon contacts: the force along the right normal with the spring magnitude k delta, and the
// right torque sign, for squares face-to-face, corner-to-face, a disk on a square's face and a
// square against a wall and an obstacle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dem_fixtures.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
constexpr double pi = 3.141592653589793;
const double L = 0.02, rho = 2700.0, h = 5e-4;

DemConfig cfg() {
  return weightless(h);
}

/// Collision loads at rest (only the springs act), ordered by id.
std::vector<core::SolidLoads> loads_of(const std::vector<SolidSpec>& solids) {
  return collision_loads(cfg(), solids);
}

/// k_xi of a pair in a case whose only solids are these two: eq. 10 with the heavier mass (the
/// stiffness mass of the case, doc/dem.md "Unequal masses"; (m_1 + m_2) / 2 = m for equal ones)
double k_n_pair(double m1, double m2) {
  return coefficients(cfg(), std::max(m1, m2)).k_n;
}
}  // namespace

TEST(PolygonContacts, SquaresFaceToFacePushAlongTheFaceNormalWithoutTorque) {
  const double delta = 0.2 * h, m = rho * L * L;
  const double d = L + 2 * h - delta;  // centre distance: faces 2h - delta apart
  const auto l =
      loads_of({square(0, L, rho, {0.5, 0.5}), square(1, L, rho, {0.5 + d, 0.5 + 0.3 * L})});
  const double F = k_n_pair(m, m) * delta;
  EXPECT_NEAR(l[0].force.x, -F, 1e-9 * F);
  EXPECT_NEAR(l[0].force.z, 0.0, 1e-9 * F);
  EXPECT_NEAR(l[1].force.x, F, 1e-9 * F);
  // the contact point is the middle of the common stretch of the faces: z = 0.5 + 0.15 L,
  // so each square feels the torque of a force at that height
  EXPECT_NEAR(l[0].torque, -(0.15 * L) * (-F), 1e-9 * F * L);
  EXPECT_NEAR(l[1].torque, -(-0.15 * L) * F, 1e-9 * F * L);
}

TEST(PolygonContacts, CornerToFaceTorqueSign) {
  // square 1 turned 45 degrees, its left corner at height e above square 0's centre
  const double delta = 0.3 * h, e = 0.2 * L, m = rho * L * L;
  const double half_diag = L / std::sqrt(2.0);
  const core::Vec2 x1{0.5 + 0.5 * L + 2 * h - delta + half_diag, 0.5 + e};
  const auto l = loads_of({square(0, L, rho, {0.5, 0.5}), square(1, L, rho, x1, 0.25 * pi)});
  const double F = k_n_pair(m, m) * delta;
  EXPECT_NEAR(l[0].force.x, -F, 1e-9 * F);
  EXPECT_NEAR(l[0].force.z, 0.0, 1e-9 * F);
  // a push in -x applied above the centre of square 0 turns it counter-clockwise
  EXPECT_GT(l[0].torque, 0.0);
  EXPECT_NEAR(l[0].torque, e * F, 1e-9 * F * L);
  // the force on square 1 passes through its centre (the corner is level with it)
  EXPECT_NEAR(l[1].torque, 0.0, 1e-9 * F * L);
  // the same corner below the centre turns square 0 clockwise
  const core::Vec2 x2{x1.x, 0.5 - e};
  const auto l2 = loads_of({square(0, L, rho, {0.5, 0.5}), square(1, L, rho, x2, 0.25 * pi)});
  EXPECT_LT(l2[0].torque, 0.0);
}

TEST(PolygonContacts, DiskOnASquareFace) {
  const double r = 0.01, delta = 0.25 * h;
  const double md = rho * pi * r * r, ms = rho * L * L;
  const auto l = loads_of({square(0, L, rho, {0.5, 0.5}),
                           disk(1, r, rho, {0.5 + 0.1 * L, 0.5 + 0.5 * L + r + 2 * h - delta})});
  const double F = k_n_pair(md, ms) * delta;
  EXPECT_NEAR(l[0].force.z, -F, 1e-9 * F);
  EXPECT_NEAR(l[1].force.z, F, 1e-9 * F);
  EXPECT_NEAR(l[1].force.x, 0.0, 1e-9 * F);
  EXPECT_NEAR(l[1].torque, 0.0, 1e-9 * F * r);
  // the push -F on the square acts 0.1 L right of its centre: clockwise
  EXPECT_NEAR(l[0].torque, -0.1 * L * F, 1e-9 * F * L);
}

TEST(PolygonContacts, TiltedSquareOnTheFloorAndOnAnObstacle) {
  // a square turned counter-clockwise by 10 degrees: its lowest corner, left of the centre,
  // touches the floor; the push is up and turns it back towards flat (clockwise)
  const double t = 10.0 * pi / 180.0, delta = 0.1 * h, m = rho * L * L;
  const double drop = 0.5 * L * (std::cos(t) + std::sin(t));  // centre height above lowest corner
  const auto l = loads_of({square(0, L, rho, {0.5, drop + 2 * h - delta}, t)});
  const double F = coefficients(cfg(), m).k_n * delta;
  EXPECT_NEAR(l[0].force.z, F, 1e-9 * F);
  EXPECT_NEAR(l[0].force.x, 0.0, 1e-9 * F);
  const double arm = 0.5 * L * (std::cos(t) - std::sin(t));  // lowest corner is at x - arm
  EXPECT_NEAR(l[0].torque, -arm * F, 1e-9 * F * L);
  EXPECT_LT(l[0].torque, 0.0);

  // the same square over a fixed triangular obstacle whose top vertex is under its flat face
  DemSolver s = solver(cfg(), 1.0, 1.0, {{{0.45, 0.2}, {0.55, 0.2}, {0.5, 0.3}}});
  s.add_solids({square(0, L, rho, {0.5 + 0.2 * L, 0.3 + 0.5 * L + 2 * h - delta})});
  const auto lo = s.predicted_collision_loads(1e-4);
  EXPECT_NEAR(lo[0].force.z, F, 1e-9 * F);
  // the vertex pushes up 0.2 L left of the square's centre: clockwise
  EXPECT_NEAR(lo[0].torque, -0.2 * L * F, 1e-9 * F * L);
}

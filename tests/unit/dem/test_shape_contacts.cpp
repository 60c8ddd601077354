// Contacts of the ellipse and the rounded polygon with every other shape (disk, square, triangle,
// ellipse, rounded polygon), the tank walls and an obstacle: on random placements near touching,
// the DEM's overlap delta = 2 dx - distance (eq. 19) and its normal are compared with a brute-force
// sampling of both real boundaries (points dl = 2e-5 apart, so the sampled distance exceeds the
// true one by at most dl).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dem_fixtures.hpp"
#include "picdem/dem/contact_geometry.hpp"
#include "picdem/geometry/shape_registry.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;
using core::Vec2;

namespace {

constexpr double kH = 5e-4, kGap = 2 * kH, kDl = 2e-5;

DemConfig cfg() {
  DemConfig c;
  c.h = kH;
  c.gravity = {0.0, 0.0};
  return c;
}

/// Points along the pieces no more than kDl apart, those within `reach` of `centre` only.
std::vector<Vec2> samples(const std::vector<geometry::BoundaryPiece>& world, const Vec2& centre,
                          double reach) {
  std::vector<Vec2> out;
  auto keep = [&](const Vec2& p) {
    if (core::norm(p - centre) < reach) out.push_back(p);
  };
  for (const auto& piece : world) {
    if (const auto* s = std::get_if<geometry::Segment>(&piece)) {
      const int n = 1 + static_cast<int>(core::norm(s->b - s->a) / kDl);
      for (int j = 0; j <= n; ++j) keep(s->a + (static_cast<double>(j) / n) * (s->b - s->a));
    } else {
      const auto& a = std::get<geometry::Arc>(piece);
      const int n = 1 + static_cast<int>(a.radius * (a.phi1 - a.phi0) / kDl);
      for (int j = 0; j <= n; ++j) {
        const double phi = a.phi0 + (a.phi1 - a.phi0) * j / n;
        keep(a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)});
      }
    }
  }
  return out;
}

struct Brute {
  double distance = INFINITY;
  Vec2 on_a, on_b;
};

Brute brute(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  Brute r;
  double best = INFINITY;
  for (const Vec2& p : a)
    for (const Vec2& q : b) {
      const double d2 = core::norm2(q - p);
      if (d2 < best) best = d2, r.on_a = p, r.on_b = q;
    }
  r.distance = std::sqrt(best);
  return r;
}

SolidSpec spec(std::int64_t id, geometry::ShapePtr shape, Vec2 x, double theta) {
  SolidSpec s;
  s.shape = std::move(shape);
  s.density = 1000.0;
  s.state.id = id;
  s.state.x = x;
  s.state.theta = theta;
  return s;
}

/// The DEM's contact of solid 0 with the partner (id 1, or -1 for a wall or obstacle); false
/// when there is none.
bool dem_contact(const std::vector<SolidSpec>& solids, const std::vector<std::vector<Vec2>>& obst,
                 std::int64_t partner, Contact& out) {
  DemSolver s = solver(cfg(), 1.0, 1.0, obst);
  s.add_solids(solids);
  for (const auto& c : s.active_contacts())
    if (c.id_i == 0 && c.id_j == partner) return out = c, true;
  return false;
}

/// Compares the DEM's delta and normal with the brute-force distance `b` (normal from the
/// partner's sample towards solid 0's, i.e. from solid 0 to the partner negated as the DEM does).
void expect_agrees(bool found, const Contact& c, const Brute& b, int& touching) {
  if (b.distance > kGap + kDl) {
    EXPECT_FALSE(found) << "no contact expected at distance " << b.distance;
    return;
  }
  if (b.distance < kGap - kDl) {
    ASSERT_TRUE(found) << "contact expected at distance " << b.distance;
    ++touching;
  }
  if (!found) return;
  // the sampled distance is at most kDl above the true one
  EXPECT_GE(c.delta, kGap - b.distance - 1e-12);
  EXPECT_LE(c.delta, kGap - b.distance + kDl);
  if (b.distance > 0.2 * kGap) {
    const Vec2 n = (b.on_b - b.on_a) / b.distance;
    EXPECT_GT(core::dot(n, c.normal), std::cos(0.05))
        << "normal " << c.normal.x << " " << c.normal.z;
  }
}

std::vector<geometry::ShapePtr> partners() {
  return {std::make_shared<const geometry::Circle>(0.012),
          square_shape(0.02),
          std::make_shared<const geometry::Polygon>(
              std::vector<Vec2>{{0.0, 0.0}, {0.03, 0.004}, {0.01, 0.02}}),
          geometry::make_ellipse(0.018, 0.006),
          geometry::make_ellipse(0.01, 0.012),
          geometry::make_rounded_polygon({{0, 0}, {0.02, 0}, {0.025, 0.015}, {0, 0.01}}, 0.003,
                                         nullptr)};
}

}  // namespace

TEST(ShapeContacts, EllipseAndRoundedPolygonAgainstEveryShape) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<geometry::ShapePtr> mine{
      geometry::make_ellipse(0.02, 0.008),
      geometry::make_rounded_polygon({{0, 0}, {0.03, 0}, {0.015, 0.02}}, 0.004, nullptr)};
  int touching = 0, trials = 0;
  for (const auto& a : mine) {
    for (const auto& b : partners()) {
      for (int trial = 0; trial < 12; ++trial, ++trials) {
        const Vec2 xa{0.5, 0.5};
        const double ta = 2 * M_PI * u(rng), tb = 2 * M_PI * u(rng), dir = 2 * M_PI * u(rng);
        const Vec2 d{std::cos(dir), std::sin(dir)};
        // partner placed along d with its support line s beyond solid 0's, then moved along d by
        // the sampled distance's excess over s: the real boundaries stay at least s apart, as
        // the imaginary gap keeps them (crossing real boundaries are outside what the
        // piece-to-piece closest points handle, doc/dem.md); s in [gap/50, 3 gap/2]
        const auto wa = to_world(a->boundary(), {xa, ta});
        const auto wb0 = to_world(b->boundary(), {{0.0, 0.0}, tb});
        const double s = kGap * (0.02 + 1.48 * u(rng));
        // each boundary's points within |xb - xa| of the other centre: the nearest points of two
        // convex solids are among them (the ray between the centres meets each boundary closer
        // than that), so the sampled distance is always finite
        auto sampled = [&](const Vec2& xb) {
          const double reach = core::norm(xb - xa) + kDl;
          return brute(samples(wa, xb, reach),
                       samples(to_world(b->boundary(), {xb, tb}), xa, reach));
        };
        Vec2 xb = xa + (core::dot(support_point(wa, d) - xa, d) +
                        core::dot(support_point(wb0, -1.0 * d), -1.0 * d) + s) *
                           d;
        xb -= (sampled(xb).distance - s) * d;
        const Brute br = sampled(xb);
        Contact c;
        const bool found = dem_contact({spec(0, a, xa, ta), spec(1, b, xb, tb)}, {}, 1, c);
        SCOPED_TRACE(a->kind() + " / " + b->kind() + " trial " + std::to_string(trial));
        expect_agrees(found, c, br, touching);
        if (HasFailure()) return;
      }
    }
  }
  EXPECT_GT(touching, trials / 2);
}

TEST(ShapeContacts, EllipseAndRoundedPolygonAgainstWallsAndAnObstacle) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<geometry::ShapePtr> mine{
      geometry::make_ellipse(0.02, 0.008),
      geometry::make_rounded_polygon({{0, 0}, {0.03, 0}, {0.015, 0.02}}, 0.004, nullptr)};
  // a triangular obstacle on the floor in the middle of the tank
  const std::vector<Vec2> tri{{0.4, 0.0}, {0.6, 0.0}, {0.5, 0.1}};
  const std::vector<geometry::BoundaryPiece> obstacle{geometry::Segment{tri[0], tri[1]},
                                                      geometry::Segment{tri[1], tri[2]},
                                                      geometry::Segment{tri[2], tri[0]}};
  int touching = 0, trials = 0;
  for (const auto& a : mine) {
    for (int trial = 0; trial < 40; ++trial, ++trials) {
      const double ta = 2 * M_PI * u(rng), s = kGap * (0.02 + 1.48 * u(rng));
      const auto w0 = to_world(a->boundary(), {{0.0, 0.0}, ta});
      Vec2 x;
      std::vector<Vec2> partner;
      std::vector<std::vector<Vec2>> obst;
      if (trial % 2 == 0) {
        // over the floor (z = 0) near x = 0.2
        x = {0.2, -core::dot(support_point(w0, {0.0, -1.0}), {0.0, 1.0}) + s};
        partner = samples({geometry::Segment{{0.1, 0.0}, {0.3, 0.0}}}, x,
                          a->bounding_radius() + 2 * kGap);
      } else {
        // against the obstacle's right face, outward normal (0.1, 0.1)/|.|
        const double along = 0.04 * (u(rng) - 0.5);
        const Vec2 n = Vec2{0.1, 0.1} / std::sqrt(0.02), foot{0.55 + along, 0.05 - along};
        x = foot + (core::dot(support_point(w0, -1.0 * n), -1.0 * n) + s) * n;
        partner = samples(obstacle, x, a->bounding_radius() + 2 * kGap);
        obst.push_back(tri);
      }
      const auto wa = to_world(a->boundary(), {x, ta});
      const Brute br = brute(samples(wa, x, 1.0), partner);
      Contact c;
      const bool found = dem_contact({spec(0, a, x, ta)}, obst, -1, c);
      SCOPED_TRACE(a->kind() + (trial % 2 ? " / obstacle" : " / floor") + " trial " +
                   std::to_string(trial));
      expect_agrees(found, c, br, touching);
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(touching, trials / 2);
}

// Closest points between boundary pieces, against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "picdem/dem/contact_geometry.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"
#include "picdem/geometry/shape_registry.hpp"

using namespace picdem;
using namespace picdem::dem;
using geometry::Arc;
using geometry::Segment;

namespace {
constexpr double pi = 3.141592653589793;
}

TEST(ContactGeometry, CircleCircleThroughArcsIsExact) {
  const geometry::Circle c1(0.3), c2(0.5);
  const auto a = to_world(c1.boundary(), {{0.0, 0.0}, 0.7});
  const auto b = to_world(c2.boundary(), {{3.0, 4.0}, -1.1});
  const ClosestPoints cp = closest_points(a, b);
  EXPECT_NEAR(cp.distance, 5.0 - 0.8, 1e-14);
  EXPECT_NEAR(cp.on_a.x, 0.3 * 0.6, 1e-14);
  EXPECT_NEAR(cp.on_a.z, 0.3 * 0.8, 1e-14);
  EXPECT_NEAR(cp.on_b.x, 3.0 - 0.5 * 0.6, 1e-14);
  EXPECT_NEAR(cp.on_b.z, 4.0 - 0.5 * 0.8, 1e-14);
}

TEST(ContactGeometry, SegmentSegmentCornerToFaceAndCrossing) {
  const Segment face{{0.0, -1.0}, {0.0, 1.0}};
  const Segment edge{{0.25, 0.5}, {1.0, 0.9}};
  const ClosestPoints cp = closest_points(face, edge);
  EXPECT_NEAR(cp.distance, 0.25, 1e-15);
  EXPECT_NEAR(cp.on_a.z, 0.5, 1e-15);
  EXPECT_FALSE(cp.face);
  const ClosestPoints x = closest_points(face, Segment{{-1.0, 0.2}, {1.0, 0.2}});
  EXPECT_EQ(x.distance, 0.0);
  EXPECT_NEAR(x.on_a.z, 0.2, 1e-15);
}

TEST(ContactGeometry, ParallelFacesMeetAtTheMiddleOfTheirCommonStretch) {
  const ClosestPoints cp =
      closest_points(Segment{{0.0, -1.0}, {0.0, 1.0}}, Segment{{0.1, 3.0}, {0.1, 0.5}});
  EXPECT_TRUE(cp.face);
  EXPECT_NEAR(cp.distance, 0.1, 1e-15);
  // common stretch z in [0.5, 1]: its ends, and its middle when both ends overlap equally
  EXPECT_NEAR(cp.end_a[0].z + cp.end_a[1].z, 1.5, 1e-15);
  core::Vec2 on_a, on_b;
  face_weighted(cp, 0.2, on_a, on_b);
  EXPECT_NEAR(on_a.z, 0.75, 1e-15);
  EXPECT_NEAR(on_b.x, 0.1, 1e-15);
  // tilted: the second face is 0.1 away from z = 0.5 and 0.15 / sqrt(1.01) from z = 1; with a
  // gap of 0.2 the point sits between the ends in proportion to the overlaps
  const ClosestPoints t =
      closest_points(Segment{{0.0, -1.0}, {0.0, 1.0}}, Segment{{0.2, 1.5}, {0.1, 0.5}});
  EXPECT_TRUE(t.face);
  EXPECT_NEAR(t.distance, 0.1, 1e-15);
  EXPECT_NEAR(t.on_a.z, 0.5, 1e-15);
  face_weighted(t, 0.2, on_a, on_b);
  const double w0 = 0.1, w1 = 0.2 - 0.15 / std::sqrt(1.01);
  EXPECT_NEAR(on_a.z, 0.5 + 0.5 * w1 / (w0 + w1), 1e-14);
}

TEST(ContactGeometry, SegmentArcInteriorAndEndpoint) {
  // full circle of radius 1 at the origin, segment the line z = 2 for x in [-1, 3]
  const Arc full{{0.0, 0.0}, 1.0, 0.0, 2 * pi};
  const ClosestPoints cp = closest_points(Segment{{-1.0, 2.0}, {3.0, 2.0}}, full);
  EXPECT_NEAR(cp.distance, 1.0, 1e-15);
  EXPECT_NEAR(cp.on_b.z, 1.0, 1e-15);
  // a quarter arc (phi in [-pi/2, 0]) cannot reach the top: its nearest point is the end at (1, 0)
  const Arc quarter{{0.0, 0.0}, 1.0, -0.5 * pi, 0.0};
  const ClosestPoints q = closest_points(Segment{{-1.0, 2.0}, {3.0, 2.0}}, quarter);
  EXPECT_NEAR(q.on_b.x, 1.0, 1e-15);
  EXPECT_NEAR(q.on_b.z, 0.0, 1e-15);
  EXPECT_NEAR(q.distance, 2.0, 1e-15);
}

// Real boundaries that cross (an overlap beyond the gap) give distance 0 at a crossing point, as
// two crossing segments do, and not the distance of a neighbouring critical point.
TEST(ContactGeometry, ArcCrossingsGiveDistanceZero) {
  // the line z = 0.6 for x in [-2, 0] crosses the unit circle at (-0.8, 0.6): on the upper half
  const Segment s{{-2.0, 0.6}, {0.0, 0.6}};
  const ClosestPoints x = closest_points(s, Arc{{0.0, 0.0}, 1.0, 0.0, pi});
  EXPECT_EQ(x.distance, 0.0);
  EXPECT_NEAR(x.on_a.x, -0.8, 1e-15);
  EXPECT_NEAR(x.on_a.z, 0.6, 1e-15);
  EXPECT_EQ(x.on_a.x, x.on_b.x);
  // the lower half is not crossed: its end (-1, 0) is 0.6 below the segment
  const ClosestPoints below = closest_points(s, Arc{{0.0, 0.0}, 1.0, pi, 2 * pi});
  EXPECT_NEAR(below.distance, 0.6, 1e-15);
  // unit circles centred 1.2 apart cross at (0.6, +-0.8): the upper halves at (0.6, 0.8) ...
  const Arc a{{0.0, 0.0}, 1.0, 0.0, pi};
  const ClosestPoints y = closest_points(a, Arc{{1.2, 0.0}, 1.0, 0.0, pi});
  EXPECT_EQ(y.distance, 0.0);
  EXPECT_NEAR(y.on_a.x, 0.6, 1e-15);
  EXPECT_NEAR(y.on_a.z, 0.8, 1e-15);
  // ... while the upper half of one and the lower half of the other do not meet: 0.8 apart on
  // the line of centres, (1, 0) and (0.2, 0)
  const ClosestPoints apart = closest_points(a, Arc{{1.2, 0.0}, 1.0, pi, 2 * pi});
  EXPECT_NEAR(apart.distance, 0.8, 1e-14);
}

TEST(ContactGeometry, SupportPointAndCircleFastPath) {
  const geometry::Circle c(0.25);
  EXPECT_EQ(c.fast_paths().centred_circle_radius, 0.25);
  const geometry::Polygon sq({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_EQ(sq.fast_paths().centred_circle_radius, 0.0);
  const auto w = to_world(sq.boundary(), {{2.0, 2.0}, 0.25 * pi});
  const core::Vec2 low = support_point(w, {0.0, -1.0});
  EXPECT_NEAR(low.x, 2.0, 1e-14);
  EXPECT_NEAR(low.z, 2.0 - std::sqrt(0.5), 1e-14);
}

// The arcs' span test (cross products against the end directions) on spans below, at and above pi
// and the whole circle, with start angles off [-pi, pi] as a rotated body gives: the distance from
// a point to the arc against the nearest of 20,001 points along it.
TEST(ContactGeometry, ArcSpanTestAgreesWithSamplingOnEverySpan) {
  const double spans[] = {0.3, 1.0, pi - 0.01, pi, pi + 0.01, 4.0, 2 * pi - 0.1, 2 * pi};
  const double starts[] = {-7.0, -2.5, 0.0, 1.3, 5.9, 11.0};
  const core::Vec2 centre{0.2, -0.1};
  const double radius = 0.7;
  unsigned state = 12345u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) * (1.0 / 16777216.0);
  };
  int checked = 0;
  for (double span : spans)
    for (double phi0 : starts) {
      const Arc arc{centre, radius, phi0, phi0 + span};
      for (int k = 0; k < 40; ++k) {
        const core::Vec2 p{centre.x + 3.0 * (uniform() - 0.5), centre.z + 3.0 * (uniform() - 0.5)};
        const double off = std::abs(std::sqrt(core::norm2(p - centre)) - radius);
        if (off < 0.05) continue;  // sampling resolves the distance to 1e-6 only away from the arc
        double sampled = std::numeric_limits<double>::infinity();
        const int n = 20000;
        for (int i = 0; i <= n; ++i) {
          const double phi = phi0 + span * i / n;
          const core::Vec2 q = centre + radius * core::Vec2{std::cos(phi), std::sin(phi)};
          sampled = std::min(sampled, std::sqrt(core::norm2(q - p)));
        }
        const ClosestPoints cp = closest_points(Segment{p, p}, arc);
        ASSERT_NEAR(cp.distance, sampled, 1e-6) << "span " << span << " phi0 " << phi0;
        const core::Vec2 on = closest_on_arc(arc, p);
        ASSERT_NEAR(std::sqrt(core::norm2(on - p)), sampled, 1e-6);
        ++checked;
      }
    }
  EXPECT_GT(checked, 1000);
}

// A body's boundary kept with its arcs' end data (the DEM's form) and placed by rotating the end
// directions gives the ends the placed arcs' angles give, and the same closest points as the plain
// pieces, for an ellipse (arcs only) and a rounded polygon (arcs and segments).
TEST(ContactGeometry, PlacedEndDataAgreeWithThePlacedPieces) {
  const geometry::ShapePtr shapes[] = {
      geometry::make_ellipse(0.02, 0.008),
      geometry::make_rounded_polygon({{-0.01, -0.01}, {0.012, -0.008}, {0.006, 0.011}}, 0.002,
                                     nullptr)};
  const geometry::Pose pa{{0.1, 0.2}, 2.7}, pb{{0.124, 0.207}, -8.1};
  for (const auto& shape : shapes) {
    const Boundary body = with_ends(shape->boundary());
    Boundary wa, wb;
    to_world(body, pa, wa);
    to_world(body, pb, wb);
    const auto plain_a = to_world(shape->boundary(), pa);
    const auto plain_b = to_world(shape->boundary(), pb);
    ASSERT_EQ(wa.pieces.size(), plain_a.size());
    int arcs = 0;
    for (std::size_t k = 0; k < plain_a.size(); ++k) {
      const auto* arc = std::get_if<Arc>(&plain_a[k]);
      if (!arc) continue;
      ++arcs;
      const ArcEnds& e = wa.ends[k];
      EXPECT_NEAR(e.u0.x, std::cos(arc->phi0), 1e-15);
      EXPECT_NEAR(e.u0.z, std::sin(arc->phi0), 1e-15);
      EXPECT_NEAR(e.u1.x, std::cos(arc->phi1), 1e-15);
      EXPECT_NEAR(e.u1.z, std::sin(arc->phi1), 1e-15);
    }
    EXPECT_GT(arcs, 0);
    const ClosestPoints kept = closest_points(wa, wb), plain = closest_points(plain_a, plain_b);
    EXPECT_NEAR(kept.distance, plain.distance, 1e-15);
    EXPECT_NEAR(kept.on_a.x, plain.on_a.x, 1e-14);
    EXPECT_NEAR(kept.on_b.z, plain.on_b.z, 1e-14);
    // the pieces near the partner (within its bounding radius + the distance, as the DEM's
    // bounding radius + gap for a pair in contact): a subset that keeps the closest points
    Boundary near_a, near_b;
    const double reach = shape->bounding_radius() + 1.01 * plain.distance;
    to_world_near(body, pa, pb.x, reach, near_a);
    to_world_near(body, pb, pa.x, reach, near_b);
    EXPECT_LT(near_a.pieces.size(), wa.pieces.size());
    EXPECT_NEAR(closest_points(near_a, near_b).distance, plain.distance, 1e-15);
    const core::Vec2 down{0.0, -1.0};
    const core::Vec2 low = support_point(wa, down), low_plain = support_point(plain_a, down);
    EXPECT_NEAR(low.z, low_plain.z, 1e-15);
  }
}

// closest_points of two boundaries skips the piece pairs whose circles' bound exceeds the best so
// far: over random poses of two curved shapes near each other its distance is the minimum over
// every pair of pieces (to keep_min_prefer_face's 1e-9 tie tolerance).
TEST(ContactGeometry, SkippedPiecePairsNeverHoldTheMinimum) {
  const geometry::ShapePtr ellipse = geometry::make_ellipse(0.02, 0.008);
  const geometry::ShapePtr rounded = geometry::make_rounded_polygon(
      {{-0.01, -0.01}, {0.012, -0.008}, {0.006, 0.011}}, 0.002, nullptr);
  const Boundary be = with_ends(ellipse->boundary()), br = with_ends(rounded->boundary());
  unsigned state = 777u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) * (1.0 / 16777216.0);
  };
  int pairs = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const geometry::Pose pa{{0.0, 0.0}, 2 * pi * uniform()};
    const double angle = 2 * pi * uniform(), dist = 0.015 + 0.03 * uniform();
    const geometry::Pose pb{{dist * std::cos(angle), dist * std::sin(angle)}, 2 * pi * uniform()};
    const Boundary& body_b = trial % 2 ? br : be;
    Boundary wa, wb;
    to_world(be, pa, wa);
    to_world(body_b, pb, wb);
    double every = std::numeric_limits<double>::infinity();
    for (const auto& p : wa.pieces)
      for (const auto& q : wb.pieces) every = std::min(every, closest_points(p, q).distance);
    const double d = closest_points(wa, wb).distance;
    ASSERT_NEAR(d, every, 1e-9 * (1.0 + every)) << "trial " << trial;
    ++pairs;
  }
  EXPECT_EQ(pairs, 1000);
}

// The graded_packing generator through the case file: sizes follow the grading curve (mass
// passing at the sieves, Kolmogorov-Smirnov by number), no two real boundaries closer than the
// gap (checked here from the boundaries, not from the generator's bounding circles), the same
// seed gives the same packing, and impossible requests fail naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "picdem/core/error.hpp"
#include "picdem/dem/parameters.hpp"

using namespace picdem;
using namespace picdem::dem;
using core::Vec2;

namespace {

core::ParamSchema schema() {
  core::ParamSchema s;
  s.real("grid/cell_size", 0.01, "h");
  declare_parameters(s);
  return s;
}

std::vector<SolidSpec> packing(const std::string& keys) {
  const std::string text =
      "grid:\n  cell_size: 0.0005\nsolids:\n  rocks:\n    type: graded_packing\n"
      "    density: 2650\n" +
      keys;
  return solids_from(core::read_case_text(text, "case.yaml", {}, schema()));
}

/// Equivalent-area diameter of a solid (the generator's size d).
double size_of(const SolidSpec& s) {
  return std::sqrt(4.0 * s.shape->mass_properties().area / M_PI);
}

/// Points along the world boundary of a solid, at most `step` apart.
std::vector<Vec2> boundary_points(const SolidSpec& s, double step) {
  const geometry::Pose pose{s.state.x, s.state.theta};
  std::vector<Vec2> out;
  for (const auto& piece : s.shape->boundary()) {
    if (const auto* seg = std::get_if<geometry::Segment>(&piece)) {
      const int n = 1 + static_cast<int>(core::norm(seg->b - seg->a) / step);
      for (int k = 0; k < n; ++k)
        out.push_back(pose.to_world(seg->a + (static_cast<double>(k) / n) * (seg->b - seg->a)));
    } else {
      const auto& a = std::get<geometry::Arc>(piece);
      const int n = 1 + static_cast<int>(a.radius * (a.phi1 - a.phi0) / step);
      for (int k = 0; k <= n; ++k) {
        const double phi = a.phi0 + (a.phi1 - a.phi0) * k / n;
        out.push_back(pose.to_world(a.centre + a.radius * Vec2{std::cos(phi), std::sin(phi)}));
      }
    }
  }
  return out;
}

/// Exact distance from the world point p to the boundary of solid s.
double distance_to(const SolidSpec& s, const Vec2& world) {
  const Vec2 p = geometry::Pose{s.state.x, s.state.theta}.to_body(world);
  double best = 1e300;
  for (const auto& piece : s.shape->boundary()) {
    if (const auto* seg = std::get_if<geometry::Segment>(&piece)) {
      const Vec2 e = seg->b - seg->a;
      const double t = std::clamp(core::dot(p - seg->a, e) / core::norm2(e), 0.0, 1.0);
      best = std::min(best, core::norm(p - (seg->a + t * e)));
      continue;
    }
    const auto& a = std::get<geometry::Arc>(piece);
    const Vec2 d = p - a.centre;
    double phi = std::atan2(d.z, d.x) - a.phi0;
    phi -= 2.0 * M_PI * std::floor(phi / (2.0 * M_PI));
    if (phi <= a.phi1 - a.phi0) {
      best = std::min(best, std::fabs(core::norm(d) - a.radius));
    } else {
      for (const double end : {a.phi0, a.phi1})
        best = std::min(best, core::norm(d - a.radius * Vec2{std::cos(end), std::sin(end)}));
    }
  }
  return best;
}

/// Checks every pair and the region's sides: disks by their exact centre distance, other
/// shapes by the exact distance from boundary points at most `step` apart (every vertex and
/// arc end among them) of each to the boundary of the other, both ways, and by no point of one
/// lying inside the other.
void expect_apart(const std::vector<SolidSpec>& s, double gap, double x0, double z0, double x1,
                  double z1) {
  const double step = gap / 20.0;
  std::vector<std::vector<Vec2>> pts;
  for (const auto& a : s) pts.push_back(boundary_points(a, step));
  double worst = 1e300;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (const Vec2& p : pts[i]) {
      worst = std::min({worst, p.x - x0, x1 - p.x, p.z - z0, z1 - p.z});
    }
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double ri = s[i].shape->fast_paths().centred_circle_radius;
      const double rj = s[j].shape->fast_paths().centred_circle_radius;
      const double dc = core::norm(s[i].state.x - s[j].state.x);
      if (ri > 0.0 && rj > 0.0) {
        worst = std::min(worst, dc - ri - rj);
        continue;
      }
      if (dc > s[i].shape->bounding_radius() + s[j].shape->bounding_radius() + 2.0 * gap) continue;
      const geometry::Pose pi{s[i].state.x, s[i].state.theta}, pj{s[j].state.x, s[j].state.theta};
      for (const Vec2& p : pts[i]) {
        worst = std::min(worst, distance_to(s[j], p));
        ASSERT_FALSE(s[j].shape->contains(pj.to_body(p))) << i << " " << j;
      }
      for (const Vec2& q : pts[j]) {
        worst = std::min(worst, distance_to(s[i], q));
        ASSERT_FALSE(s[i].shape->contains(pi.to_body(q))) << i << " " << j;
      }
    }
  }
  EXPECT_GE(worst, gap * (1.0 - 1e-9));
}

}  // namespace

TEST(GradedPacking, MassPassingAtTheSievesFollowsTheTable) {
  // N = 3000 disks; the binomial standard error of a passing fraction is below 0.01 at this N,
  // the tolerance 0.03 is about three of them
  const auto s = packing(
      "    region: [0, 0, 0.6, 0.6]\n    count: 3000\n"
      "    sieves: [0.002, 0.004, 0.008, 0.016, 0.02]\n    passing: [0, 0.1, 0.45, 0.9, 1]\n");
  ASSERT_EQ(s.size(), 3000u);
  const std::vector<double> sieves{0.004, 0.008, 0.016}, table{0.1, 0.45, 0.9};
  double total = 0.0;
  for (const auto& a : s) total += a.state.mass;
  for (std::size_t k = 0; k < sieves.size(); ++k) {
    double below = 0.0;
    for (const auto& a : s)
      if (size_of(a) <= sieves[k]) below += a.state.mass;
    EXPECT_NEAR(below / total, table[k], 0.03) << "sieve " << sieves[k];
  }
  for (const auto& a : s) {
    EXPECT_GE(size_of(a), 0.002 * (1 - 1e-12));
    EXPECT_LE(size_of(a), 0.02 * (1 + 1e-12));
  }
}

TEST(GradedPacking, NumberSizesPassKolmogorovSmirnov) {
  // by number, d_min/d50/d_max: F(d) linear in ln d on each half; KS statistic below the 1%
  // critical value 1.63 / sqrt(N) for mixed disks, polygons and ellipses
  const auto s = packing(
      "    region: [0, 0, 0.5, 0.5]\n    count: 1200\n    basis: number\n"
      "    d_min: 0.003\n    d50: 0.006\n    d_max: 0.015\n"
      "    class_shapes: disk, polygon, ellipse\n    class_densities: [2650, 3000, 8000]\n");
  ASSERT_EQ(s.size(), 1200u);
  std::vector<double> d;
  int kinds[3] = {0, 0, 0};
  for (const auto& a : s) {
    d.push_back(size_of(a));
    const std::string k = a.shape->kind();
    const int c = k == "circle" ? 0 : k == "polygon" ? 1 : 2;
    ++kinds[c];
    EXPECT_EQ(a.density, (std::vector<double>{2650.0, 3000.0, 8000.0}[c])) << k;
  }
  for (int c : kinds) EXPECT_NEAR(c / 1200.0, 1.0 / 3.0, 0.05);
  std::sort(d.begin(), d.end());
  const auto cdf = [](double x) {
    if (x <= 0.006) return 0.5 * std::log(x / 0.003) / std::log(2.0);
    return 0.5 + 0.5 * std::log(x / 0.006) / std::log(2.5);
  };
  double ks = 0.0;
  const double n = static_cast<double>(d.size());
  for (std::size_t k = 0; k < d.size(); ++k)
    ks = std::max({ks, std::fabs(cdf(d[k]) - k / n), std::fabs(cdf(d[k]) - (k + 1) / n)});
  EXPECT_LT(ks, 1.63 / std::sqrt(n));
}

TEST(GradedPacking, RealBoundariesStayTheGapApartInABox) {
  const auto s = packing(
      "    region: [0.01, 0.02, 0.2, 0.15]\n    solid_fraction: 0.3\n    seed: 7\n"
      "    d_min: 0.004\n    d50: 0.008\n    d_max: 0.02\n    class_shapes: polygon, ellipse, "
      "disk\n");
  ASSERT_GT(s.size(), 100u);
  expect_apart(s, 0.001, 0.01, 0.02, 0.2, 0.15);
}

TEST(GradedPacking, RealBoundariesStayTheGapApartWhenPoured) {
  const auto s = packing(
      "    region: [0, 0, 0.1, 0.3]\n    count: 300\n    placement: pour\n    seed: 3\n"
      "    d_min: 0.003\n    d50: 0.005\n    d_max: 0.012\n    class_shapes: disk, polygon, "
      "ellipse\n");
  ASSERT_EQ(s.size(), 300u);
  expect_apart(s, 0.001, 0.0, 0.0, 0.1, 0.3);
  // poured: resting on the floor, not spread over the region
  double top = 0.0, bottom = 1.0;
  for (const auto& a : s) {
    top = std::max(top, a.state.x.z);
    bottom = std::min(bottom, a.state.x.z - a.shape->bounding_radius());
  }
  EXPECT_NEAR(bottom, 0.001, 1e-9);
  EXPECT_LT(top, 0.2);
}

TEST(GradedPacking, SameSeedSamePackingOtherSeedAnother) {
  const std::string keys =
      "    region: [0, 0, 0.2, 0.2]\n    count: 200\n    d_min: 0.003\n    d50: 0.005\n"
      "    d_max: 0.01\n    class_shapes: disk, polygon\n";
  const auto a = packing(keys), b = packing(keys), c = packing(keys + "    seed: 2\n");
  ASSERT_EQ(a.size(), b.size());
  bool differs = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].state.x.x, b[k].state.x.x);
    EXPECT_EQ(a[k].state.x.z, b[k].state.x.z);
    EXPECT_EQ(a[k].state.theta, b[k].state.theta);
    EXPECT_EQ(a[k].state.mass, b[k].state.mass);
    differs = differs || a[k].state.x.x != c[k].state.x.x;
  }
  EXPECT_TRUE(differs);
}

namespace {
std::string error_of(const std::string& keys) {
  try {
    packing(keys);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(GradedPacking, ImpossibleRequestsNameTheKey) {
  const std::string grading = "    d_min: 0.004\n    d50: 0.006\n    d_max: 0.01\n";
  // a box filled to 0.8 by random sequential addition (jams near 0.55 for disks)
  auto e = error_of("    region: [0, 0, 0.1, 0.1]\n    solid_fraction: 0.8\n" + grading);
  EXPECT_NE(e.find("cannot hold"), std::string::npos) << e;
  EXPECT_NE(e.find("solids/rocks"), std::string::npos) << e;
  // poured higher than the region
  e = error_of("    region: [0, 0, 0.05, 0.05]\n    count: 400\n    placement: pour\n" + grading);
  EXPECT_NE(e.find("lands above the region's top"), std::string::npos) << e;
  e = error_of("    region: [0, 0, 0.005, 0.1]\n    count: 4\n" + grading);
  EXPECT_NE(e.find("wider than the region"), std::string::npos) << e;
  e = error_of(
      "    region: [0, 0, 0.1, 0.1]\n    count: 4\n    sieves: [0.002, 0.004]\n"
      "    passing: [0.1, 1]\n");
  EXPECT_NE(e.find("solids/rocks/passing"), std::string::npos) << e;
  e = error_of(
      "    region: [0, 0, 0.1, 0.1]\n    count: 4\n    sieves: [0.004, 0.002]\n"
      "    passing: [0, 1]\n");
  EXPECT_NE(e.find("increase strictly"), std::string::npos) << e;
  e = error_of("    region: [0, 0, 0.1, 0.1]\n    count: 4\n    class_shapes: disk, cube\n" +
               grading);
  EXPECT_NE(e.find("class_shapes"), std::string::npos) << e;
  e = error_of(
      "    region: [0, 0, 0.1, 0.1]\n    count: 4\n    class_shapes: disk, polygon\n"
      "    class_densities: [2650]\n" +
      grading);
  EXPECT_NE(e.find("class_densities"), std::string::npos) << e;
  e = error_of("    region: [0, 0, 0.1, 0.1]\n    count: 4\n    solid_fraction: 0.2\n" + grading);
  EXPECT_NE(e.find("either count or solid_fraction"), std::string::npos) << e;
  e = error_of(
      "    region: [0, 0, 0.1, 0.1]\n    count: 4\n    d_min: 0.006\n    d50: 0.004\n"
      "    d_max: 0.01\n");
  EXPECT_NE(e.find("d_min < d50 < d_max"), std::string::npos) << e;
}

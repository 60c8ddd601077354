// Cut cells of shapes mixing arcs and segments (a stadium, a half disc): the invariants of
// cut_cell_checks.hpp at random placements and on the lattice, where arc ends and flat sides lie
// on grid lines (split from test_cut_cells.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "cut_cell_checks.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/outline.hpp"

using namespace picdem::geometry;
using namespace cut_cell_checks;

namespace {

/// A stadium: a 2L x 2R rectangle with half discs on its short sides (body frame: centre 0).
class Stadium : public Shape {
 public:
  Stadium(double L, double R) : L_(L), R_(R) {}
  std::string kind() const override { return "stadium"; }
  std::vector<BoundaryPiece> boundary() const override {
    return {Segment{{-L_, -R_}, {L_, -R_}}, Arc{{L_, 0}, R_, -M_PI / 2, M_PI / 2},
            Segment{{L_, R_}, {-L_, R_}}, Arc{{-L_, 0}, R_, M_PI / 2, 3 * M_PI / 2}};
  }
  MassProperties mass_properties() const override {
    // rectangle + two half discs, each offset by L (parallel axis from the flat side's centre)
    const double rect = 4 * L_ * R_, half = 0.5 * M_PI * R_ * R_;
    const double J = rect * (4 * L_ * L_ + 4 * R_ * R_) / 12 +
                     2 * (M_PI * std::pow(R_, 4) / 4 + half * (L_ * L_ + 8 * L_ * R_ / (3 * M_PI)));
    return {rect + 2 * half, J};
  }
  double bounding_radius() const override { return L_ + R_; }
  bool contains(const Vec2& p) const override {
    if (std::fabs(p.x) <= L_) return std::fabs(p.z) <= R_;
    return picdem::core::norm(p - Vec2{p.x > 0 ? L_ : -L_, 0}) <= R_;
  }
  double perimeter() const { return 4 * L_ + 2 * M_PI * R_; }

 private:
  double L_, R_;
};

/// A half disc, flat side vertical on the left (body frame: centroid at 0).
class HalfDisc : public Shape {
 public:
  explicit HalfDisc(double R) : R_(R), e_(4 * R / (3 * M_PI)) {}
  std::string kind() const override { return "half_disc"; }
  std::vector<BoundaryPiece> boundary() const override {
    return {Arc{{-e_, 0}, R_, -M_PI / 2, M_PI / 2}, Segment{{-e_, R_}, {-e_, -R_}}};
  }
  MassProperties mass_properties() const override {
    const double A = 0.5 * M_PI * R_ * R_;
    return {A, M_PI * std::pow(R_, 4) / 4 - A * e_ * e_};
  }
  double bounding_radius() const override { return std::hypot(e_, R_); }
  bool contains(const Vec2& p) const override {
    return p.x >= -e_ && picdem::core::norm(p - Vec2{-e_, 0}) <= R_;
  }
  double perimeter() const { return M_PI * R_ + 2 * R_; }
  double offset() const { return e_; }

 private:
  double R_, e_;
};

}  // namespace

TEST(CutCells, RandomShapesMixingArcsAndSegments) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double h = 0.01 + 0.2 * u(rng);
    const double R = h * (0.2 + 8.0 * u(rng));
    ShapePtr shape;
    double perimeter;
    if (trial % 2 == 0) {
      auto st = std::make_shared<Stadium>(h * 6.0 * u(rng), R);
      perimeter = st->perimeter();
      shape = st;
    } else {
      auto hd = std::make_shared<HalfDisc>(R);
      perimeter = hd->perimeter();
      shape = hd;
    }
    const Vec2 origin{-1.0 + 2.0 * u(rng), -1.0 + 2.0 * u(rng)};
    SolidPlacement s{trial, shape, {{4.0 * u(rng), 3.0 * u(rng)}, 6.0 * u(rng)}};
    const auto w = window_around(bounding_box(*s.shape, s.pose), origin, h, 2);
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, perimeter, 1e-12);
    if (HasFailure()) return;
  }
}

TEST(CutCellsDegenerate, ArcEndsAndFlatSidesOnGridLines) {
  // Unrotated stadiums and half discs on a lattice of h/4: arc ends on grid lines and corners,
  // flat sides along grid lines, arcs tangent to lines.
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> q(0, 1000);
  const GridWindow w{{0.0, 0.0}, 1.0, {-2, 16, -2, 16}};
  int flat_on_lattice = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const double R = 0.25 * (2 + q(rng) % 12);
    ShapePtr shape;
    double perimeter;
    Vec2 x{5.0 + 0.25 * (q(rng) % 12), 5.0 + 0.25 * (q(rng) % 12)};
    if (trial % 2 == 0) {
      auto st = std::make_shared<Stadium>(0.25 * (q(rng) % 10), R);
      perimeter = st->perimeter();
      shape = st;
    } else {
      auto hd = std::make_shared<HalfDisc>(R);
      perimeter = hd->perimeter();
      // the flat side exactly on the lattice: x.x - e == lattice value in floating point
      const double want = x.x;
      x.x = want + hd->offset();
      for (int step = 0; step < 8 && x.x - hd->offset() != want; ++step) {
        x.x = std::nextafter(x.x, x.x - hd->offset() < want ? 1e300 : -1e300);
      }
      flat_on_lattice += x.x - hd->offset() == want ? 1 : 0;
      shape = hd;
    }
    const SolidPlacement s{0, shape, {x, 0.0}};
    const CutCells cc = build_cut_cells(w, {s}, {}, keep_all());
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_invariants(cc, s, perimeter, 1e-12);
    if (HasFailure()) return;
  }
  EXPECT_GT(flat_on_lattice, 250);  // of 300 (x - e == want is not always reachable)
}

// The fluid next to bodies (fluid/bodies.hpp) against values worked by hand: the rigid velocity
// v + omega x r on the faces a body closes (0 on an obstacle's), the FLIP base on closed faces
// and the cells closed to reseeding.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "picdem/fluid/bodies.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem;
using core::Vec2;
using grid::Stagger;

namespace {

// 8 x 6 cells of h = 0.1; a 0.3 x 0.3 square body centred at (0.3, 0.3) closes the faces inside
// [0.15, 0.45]^2: FaceX i = 2..4, k = 2, 3 and FaceZ i = 2, 3, k = 2..4. An obstacle over
// [0.57, 0.69] x [0.05, 0.27] closes FaceX (6, 1) only (every other face it touches stays open).
struct Scene {
  grid::GridSpec spec;
  std::unique_ptr<grid::Decomposition> d;
  geometry::CutCells cut;
  fluid::Apertures E;
  Scene() {
    spec.nx = 8, spec.nz = 6, spec.h = 0.1;
    d = std::make_unique<grid::Decomposition>(spec, core::Comm(MPI_COMM_SELF), 1);
    const std::vector<Vec2> square = {{-0.15, -0.15}, {0.15, -0.15}, {0.15, 0.15}, {-0.15, 0.15}};
    const std::vector<geometry::SolidPlacement> solids = {
        {4, std::make_shared<geometry::Polygon>(square), {{0.3, 0.3}, 0.0}}};
    const std::vector<geometry::Obstacle> obstacles = {
        {"block", {{{0.57, 0.05}, {0.69, 0.05}, {0.69, 0.27}, {0.57, 0.27}}}}};
    const geometry::GridWindow window{spec.origin, spec.h, d->storage(Stagger::Cell)};
    geometry::CutCellOptions options;
    options.tiny_fraction = 0.0;
    cut = geometry::build_cut_cells(window, solids, obstacles, options);
    E = fluid::open_apertures(*d);
    for (auto [e, c] : {std::pair{&E.E_x, Stagger::FaceX}, std::pair{&E.E_z, Stagger::FaceZ}}) {
      const auto b = e->storage();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i)
          (*e)(i, k) = std::min((*e)(i, k), c == Stagger::FaceX ? cut.E_x(i, k) : cut.E_z(i, k));
    }
  }
};

bool closed_by_body_x(int i, int k) {
  return i >= 2 && i <= 4 && k >= 2 && k <= 3;
}
bool closed_by_body_z(int i, int k) {
  return i >= 2 && i <= 3 && k >= 2 && k <= 4;
}

}  // namespace

TEST(RigidFaceVelocities, BodyAndObstacleFaces) {
  Scene s;
  const auto& d = *s.d;
  grid::FaceField u(d, Stagger::FaceX, 9.0), w(d, Stagger::FaceZ, 9.0);
  grid::GridArray<signed char> u_valid(d, Stagger::FaceX, 0), w_valid(d, Stagger::FaceZ, 0);
  core::SolidState body;
  body.id = 4, body.x = {0.3, 0.3}, body.v = {0.1, -0.2}, body.omega = 2.0;
  fluid::rigid_face_velocities({body}, s.cut, s.E, d, u, w, u_valid, w_valid);
  // u = v_x - omega (z - 0.3): 0.2 at z = 0.25 (k = 2), 0 at z = 0.35 (k = 3);
  // w = v_z + omega (x - 0.3): -0.3 at x = 0.25 (i = 2), -0.1 at x = 0.35 (i = 3).
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i <= 8; ++i) {
      if (closed_by_body_x(i, k)) {
        EXPECT_NEAR(u(i, k), k == 2 ? 0.2 : 0.0, 1e-15) << i << " " << k;
        EXPECT_EQ(u_valid(i, k), 1) << i << " " << k;
      } else if (i == 6 && k == 1) {
        EXPECT_EQ(u(i, k), 0.0);  // the obstacle's face
        EXPECT_EQ(u_valid(i, k), 1);
      } else {
        EXPECT_EQ(u(i, k), 9.0) << i << " " << k;  // open, or a tank wall
        EXPECT_EQ(u_valid(i, k), 0) << i << " " << k;
      }
    }
  for (int k = 0; k <= 6; ++k)
    for (int i = 0; i < 8; ++i) {
      if (closed_by_body_z(i, k)) {
        EXPECT_NEAR(w(i, k), i == 2 ? -0.3 : -0.1, 1e-15) << i << " " << k;
        EXPECT_EQ(w_valid(i, k), 1) << i << " " << k;
      } else {
        EXPECT_EQ(w(i, k), 9.0) << i << " " << k;
        EXPECT_EQ(w_valid(i, k), 0) << i << " " << k;
      }
    }
}

TEST(RigidFaceVelocities, FlipBaseOnClosedFacesAndReseedMask) {
  Scene s;
  const auto& d = *s.d;
  fluid::FluidState f(d);
  f.apertures = s.E;
  const auto bu = f.u.storage(), bw = f.w.storage();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i) f.u(i, k) = 10.0 * i + k, f.u_old(i, k) = -1.0;
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i) f.w(i, k) = 10.0 * i - k, f.w_old(i, k) = -1.0;
  fluid::rigid_faces_into_flip_base(s.spec, f);
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i <= 8; ++i) {
      const bool closed = closed_by_body_x(i, k) || (i == 6 && k == 1);  // walls i = 0, 8 kept
      EXPECT_EQ(f.u_old(i, k), closed ? 10.0 * i + k : -1.0) << i << " " << k;
    }
  for (int k = 0; k <= 6; ++k)
    for (int i = 0; i < 8; ++i)
      EXPECT_EQ(f.w_old(i, k), closed_by_body_z(i, k) ? 10.0 * i - k : -1.0) << i << " " << k;

  // Reseeding skips every cell a body or obstacle reaches into: cells 1..4 x 1..4 (the body) and
  // (5, 0..2) and (6, 0..2) (the obstacle); every other cell keeps its
  // state.
  fluid::CellStates cells(d, Stagger::Cell, static_cast<signed char>(grid::CellState::Fluid));
  const auto mask = fluid::reseed_cells(cells, s.cut);
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 8; ++i) {
      const bool cut = (i >= 1 && i <= 4 && k >= 1 && k <= 4) || (i >= 5 && i <= 6 && k <= 2);
      EXPECT_EQ(mask(i, k),
                static_cast<signed char>(cut ? grid::CellState::Solid : grid::CellState::Fluid))
          << i << " " << k;
    }
}

// The mixture velocity (E u + (h - E) U_n) / h on the faces the body and the obstacle cut, in u
// and u_old alike; closed, open and wall faces untouched. Hand-worked open fractions e = E / h:
// the body's edges at 0.15 and 0.45 halve FaceX (2..4, 1), (2..4, 4) and FaceZ (1, 2..4),
// (4, 2..4); the obstacle leaves e = 0.5 on FaceX (6, 0), 0.3 on (6, 2), 0.7 on FaceZ (5, 1..2)
// and 0.1 on (6, 1..2).
TEST(MixCutFaces, FluxPerLengthOfFluidAndSolid) {
  Scene s;
  const auto& d = *s.d;
  fluid::FluidState f(d);
  f.apertures = s.E;
  f.u.fill(1.0), f.w.fill(1.0), f.u_old.fill(3.0), f.w_old.fill(3.0);
  core::SolidState body;
  body.id = 4, body.x = {0.3, 0.3}, body.v = {0.1, -0.2}, body.omega = 2.0;
  fluid::mix_cut_faces({body}, s.cut, d, f);
  // (e, U_n) of every cut face; U_n: u = 0.1 - 2 (z - 0.3), w = -0.2 + 2 (x - 0.3), obstacle 0
  auto expect = [](double got, double e, double U, double v, const char* what, int i, int k) {
    EXPECT_NEAR(got, e * v + (1.0 - e) * U, 1e-12) << what << " " << i << " " << k;
  };
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i <= 8; ++i) {
      double e = 1.0, U = 0.0;
      if (i >= 2 && i <= 4 && k == 1) e = 0.5, U = 0.4;   // z = 0.15
      if (i >= 2 && i <= 4 && k == 4) e = 0.5, U = -0.2;  // z = 0.45
      if (i == 6 && k == 0) e = 0.5;
      if (i == 6 && k == 2) e = 0.3;
      expect(f.u(i, k), e, U, 1.0, "u", i, k);
      expect(f.u_old(i, k), e, U, 3.0, "u_old", i, k);
    }
  for (int k = 0; k <= 6; ++k)
    for (int i = 0; i < 8; ++i) {
      double e = 1.0, U = 0.0;
      if (i == 1 && k >= 2 && k <= 4) e = 0.5, U = -0.5;  // x = 0.15
      if (i == 4 && k >= 2 && k <= 4) e = 0.5, U = 0.1;   // x = 0.45
      if (i == 5 && (k == 1 || k == 2)) e = 0.7;
      if (i == 6 && (k == 1 || k == 2)) e = 0.1;
      expect(f.w(i, k), e, U, 1.0, "w", i, k);
      expect(f.w_old(i, k), e, U, 3.0, "w_old", i, k);
    }
}

// On a fluid-air face a body or obstacle cuts, theta >= theta_min h / E; full faces, closed
// faces, faces already above the bound and faces off the surface (theta 1) keep theta. Open
// lengths of the scene: FaceZ (1, 2..4) 0.5 h (the square), FaceZ (6, 1) 0.1 h and FaceX (6, 2)
// 0.3 h (the block), FaceX (2, 2) closed, FaceZ (7, 3) full.
TEST(OpenLengthSurfaceFractions, BoundOnCutFacesOnly) {
  Scene s;
  const auto& d = *s.d;
  const double h = 0.1, theta_min = 0.05;
  ASSERT_NEAR(s.cut.E_z(1, 3), 0.5 * h, 1e-12);
  ASSERT_NEAR(s.cut.E_z(6, 1), 0.1 * h, 1e-12);
  ASSERT_NEAR(s.cut.E_x(6, 2), 0.3 * h, 1e-12);
  ASSERT_EQ(s.cut.E_x(2, 2), 0.0);
  ASSERT_EQ(s.cut.E_z(7, 3), h);
  fluid::SurfaceFractions t{grid::FaceField(d, Stagger::FaceX, 1.0),
                            grid::FaceField(d, Stagger::FaceZ, 1.0)};
  t.theta_z(1, 3) = theta_min;
  t.theta_z(6, 1) = theta_min;
  t.theta_x(6, 2) = 0.3;
  t.theta_x(2, 2) = theta_min;
  t.theta_z(7, 3) = theta_min;
  fluid::open_length_surface_fractions(s.cut, theta_min, h, t);
  EXPECT_NEAR(t.theta_z(1, 3), 0.1, 1e-12);  // 0.05 h / 0.5 h
  EXPECT_NEAR(t.theta_z(6, 1), 0.5, 1e-12);  // 0.05 h / 0.1 h
  EXPECT_EQ(t.theta_x(6, 2), 0.3);           // above 0.05 h / 0.3 h
  EXPECT_EQ(t.theta_x(2, 2), theta_min);     // closed: no flux, no bound
  EXPECT_EQ(t.theta_z(7, 3), theta_min);     // full face
  for (int k = 0; k < 6; ++k)                // every other face kept its 1
    for (int i = 0; i <= 8; ++i)
      if (!((i == 6 && k == 2) || (i == 2 && k == 2))) {
        EXPECT_EQ(t.theta_x(i, k), 1.0) << i << " " << k;
      }
}

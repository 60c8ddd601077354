// The coupling phases against values worked by hand: the solid couplings of the pressure equation
// (rows a_{s,c}, quadrature load F_q, predicted velocity V*, eq. 6), the damping of particles in
// contact gaps (eq. 20) and the solids' snapshot (ordered by id, matched by id across the DEM).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/body_loads.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem;
using core::Vec2;

namespace {

constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kAir = static_cast<signed char>(grid::CellState::Air);

// 6 x 6 cells of h = 0.1 on this process alone.
grid::GridSpec small_spec() {
  grid::GridSpec s;
  s.nx = 6, s.nz = 6, s.h = 0.1;
  return s;
}

core::SolidState state(std::int64_t id, Vec2 x, Vec2 v = {}, double omega = 0.0) {
  core::SolidState st;
  st.id = id, st.x = x, st.v = v, st.omega = omega;
  return st;
}

}  // namespace

// A 0.1 x 0.2 rectangle centred at (0.3, 0.35): its edges x = 0.25, 0.35 and z = 0.25, 0.45 cut
// cells i = 2, 3 and k = 2, 3, 4 through their middles. Per cell, with r from the centre of mass:
//   a = (int n dl, int r x n dl): (2,2) (-0.05, -0.05, -0.0025)  (3,2) (0.05, -0.05, 0.0025)
//                                 (2,3) (-0.1, 0, 0)             (3,3) (0.1, 0, 0)
//                                 (2,4) (-0.05, 0.05, 0.0025)    (3,4) (0.05, 0.05, -0.0025)
// F_q = -int rho g.(x - x_c) (n, r x n) dl = 9810 int (z - z_c) (n, r x n) dl:
//   force x: -12.2625 on (2,2) and (3,4), +12.2625 on (3,2) and (2,4), 0 elsewhere (z-parts 0);
//   torque: 9810 int (z - z_c)(r x n) dl = -/+ 9810 / 12000 = -/+ 0.8175, negative on (2,2),
//   (2,4), (3,3), positive on (3,2), (2,3), (3,4).
// Cell (3,4) is air: its piece is left out of the rows and of F_q.
TEST(SolidCouplings, RowsQuadratureLoadAndPredictedVelocityOfARectangle) {
  const core::Comm self(MPI_COMM_SELF);
  const auto spec = small_spec();
  grid::Decomposition d(spec, self, 1);
  const std::vector<Vec2> verts = {{-0.05, -0.1}, {0.05, -0.1}, {0.05, 0.1}, {-0.05, 0.1}};
  coupling::SolidScene scene;
  scene.placements.push_back({7, std::make_shared<geometry::Polygon>(verts), {{0.3, 0.35}, 0.0}});
  core::SolidState st = state(7, {0.3, 0.35}, {0.1, -0.2}, 0.5);
  st.mass = 20.0, st.inertia = 0.1;
  scene.states.push_back(st);
  fluid::Apertures E;
  const auto cut = coupling::cut_cells(scene, d, 0.0, E);
  fluid::CellStates cells(d, grid::Stagger::Cell, kFluid);
  cells(3, 4) = kAir;
  const std::vector<core::SolidLoads> collision = {{7, {3.0, -4.0}, 0.02}};
  const fluid::QuadratureOptions q{true, 1000.0, {0.0, -9.81}};
  const double dt = 1e-3;
  const auto out = fluid::solid_couplings(scene.states, cut, cells, d, collision, q, dt);
  ASSERT_EQ(out.size(), 1u);
  const auto& c = out[0];
  EXPECT_EQ(c.id, 7);
  EXPECT_EQ(c.mass, 20.0);
  EXPECT_EQ(c.inertia, 0.1);
  const std::map<std::pair<int, int>, std::array<double, 3>> expected = {
      {{2, 2}, {-0.05, -0.05, -0.0025}},
      {{3, 2}, {0.05, -0.05, 0.0025}},
      {{2, 3}, {-0.1, 0.0, 0.0}},
      {{3, 3}, {0.1, 0.0, 0.0}},
      {{2, 4}, {-0.05, 0.05, 0.0025}}};
  ASSERT_EQ(c.cells.size(), expected.size());
  ASSERT_EQ(c.a.size(), expected.size());
  for (std::size_t n = 0; n < c.cells.size(); ++n) {
    const int i = static_cast<int>(c.cells[n] % spec.nx),
              k = static_cast<int>(c.cells[n] / spec.nx);
    ASSERT_EQ(spec.cell_gid(i, k), c.cells[n]);
    const auto it = expected.find({i, k});
    ASSERT_NE(it, expected.end()) << "cell " << i << " " << k;
    for (int m = 0; m < 3; ++m)
      EXPECT_NEAR(c.a[n][static_cast<std::size_t>(m)], it->second[static_cast<std::size_t>(m)],
                  1e-15)
          << "cell " << i << " " << k << " component " << m;
  }
  // F_q over the five fluid cells: (-12.2625 + 12.2625 + 12.2625, 0), torque -0.8175.
  EXPECT_NEAR(c.load[0], 12.2625, 1e-11);
  EXPECT_NEAR(c.load[1], 0.0, 1e-11);
  EXPECT_NEAR(c.load[2], -0.8175, 1e-12);
  // V* = V + dt (g + (F_coll + F_q) / M), omega* = omega + dt (T_coll + T_q) / I
  EXPECT_NEAR(c.v_star[0], 0.1 + dt * (3.0 + 12.2625) / 20.0, 1e-14);
  EXPECT_NEAR(c.v_star[1], -0.2 + dt * (-9.81 - 4.0 / 20.0), 1e-14);
  EXPECT_NEAR(c.v_star[2], 0.5 + dt * (0.02 - 0.8175) / 0.1, 1e-13);

  // Without the quadrature: no load, V* from gravity and the collision only.
  const fluid::QuadratureOptions one_point{false, 1000.0, {0.0, -9.81}};
  const auto plain = fluid::solid_couplings(scene.states, cut, cells, d, collision, one_point, dt);
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_EQ(plain[0].load[0], 0.0);
  EXPECT_EQ(plain[0].load[2], 0.0);
  EXPECT_NEAR(plain[0].v_star[0], 0.1 + dt * 3.0 / 20.0, 1e-15);
  EXPECT_NEAR(plain[0].v_star[2], 0.5 + dt * 0.02 / 0.1, 1e-15);
}

// Eq. 20 with h = 0.01, beta = 0.2: the band of a contact is 0.04 long (along the tangent) and
// 0.02 wide; C = beta + (1 - beta) along / 0.02.
TEST(GapDamping, BandAndLinearFactorOfEquation20) {
  const double h = 0.01, beta = 0.2;
  std::vector<dem::Contact> contacts = {
      {1, 2, {0.5, 0.5}, {1.0, 0.0}, 1e-4},      // tangent along z
      {2, 3, {0.505, 0.522}, {0.0, 1.0}, 1e-4},  // tangent along x
      {4, -1, {0.8, 0.8}, {1.0, 0.0}, 0.0},      // not in contact: no band
  };
  particles::ParticleSet ps;
  const double c4[4] = {1.0, 2.0, 3.0, 4.0};
  const std::vector<Vec2> at = {
      {0.5, 0.5},     // the contact point: C = beta
      {0.505, 0.51},  // along 0.01, across 0.005: C = 0.2 + 0.8 * 0.5 = 0.6
      {0.5, 0.475},   // along 0.025: outside the band
      {0.512, 0.5},   // across 0.012 > h: outside
      {0.5, 0.515},   // first band 0.2 + 0.8 * 0.75 = 0.8, second 0.2 + 0.8 * 0.25 = 0.4: 0.4
      {0.8, 0.8}};    // at an inactive contact
  for (std::size_t n = 0; n < at.size(); ++n)
    ps.push_back(static_cast<std::int64_t>(n), at[n], {1.0, -2.0}, c4);
  const double C[] = {0.2, 0.6, 1.0, 1.0, 0.4, 1.0};
  EXPECT_EQ(coupling::damp_gap_particles(ps, contacts, h, beta), 3);
  const double tol = 1e-14;  // the positions' differences carry round-off of 1e-17
  for (std::size_t n = 0; n < at.size(); ++n) {
    EXPECT_NEAR(ps.u[n], C[n], tol) << n;
    EXPECT_NEAR(ps.w[n], -2.0 * C[n], tol) << n;
    EXPECT_NEAR(ps.cxx[n], 1.0 * C[n], tol) << n;
    EXPECT_NEAR(ps.cxz[n], 2.0 * C[n], tol) << n;
    EXPECT_NEAR(ps.czx[n], 3.0 * C[n], tol) << n;
    EXPECT_NEAR(ps.czz[n], 4.0 * C[n], tol) << n;
  }
  // beta = 1 damps nothing
  EXPECT_EQ(coupling::damp_gap_particles(ps, contacts, h, 1.0), 0);
  EXPECT_NEAR(ps.u[0], 0.2, 1e-15);
}

// The snapshot at X^{n+1} is matched to the cut cells' bodies of X^n by id, not by position:
// solid 3 left this rank's view (keeps its old motion), 12 is new (not a body of the cut cells).
TEST(SolidSnapshot, MotionsMatchedById) {
  coupling::SolidScene before, after;
  before.states = {state(3, {0.1, 0.1}, {1.0, 0.0}), state(7, {0.2, 0.2}, {2.0, 0.0}),
                   state(9, {0.3, 0.3}, {3.0, 0.0})};
  after.states = {state(7, {0.25, 0.2}, {-2.0, 0.5}, 1.5), state(9, {0.3, 0.35}, {0.0, 3.0}),
                  state(12, {0.9, 0.9}, {4.0, 4.0})};
  EXPECT_EQ(after.index_of(7), 0);
  EXPECT_EQ(after.index_of(12), 2);
  EXPECT_EQ(after.index_of(3), -1);
  EXPECT_EQ(before.index_of(3), 0);
  EXPECT_EQ(before.index_of(8), -1);
  const auto m = coupling::motions_at(before, after);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].id, 3);
  EXPECT_EQ(m[0].v.x, 1.0);
  EXPECT_EQ(m[0].x.x, 0.1);
  EXPECT_EQ(m[1].id, 7);
  EXPECT_EQ(m[1].v.x, -2.0);
  EXPECT_EQ(m[1].omega, 1.5);
  EXPECT_EQ(m[1].x.x, 0.25);
  EXPECT_EQ(m[2].id, 9);
  EXPECT_EQ(m[2].v.z, 3.0);
}

// scene_of: every solid a rank sees (owned and ghosts), ordered by id, each placement at its
// state's pose. Solids are given in shuffled id order on a tank cut into one strip per rank, all
// within contact reach of the strips' borders when there are several ranks.
TEST(SolidSnapshot, SceneOfTheDemIsOrderedById) {
  const core::Comm comm;
  const double L = 1.0, H = 0.5;
  dem::DemConfig cfg;
  cfg.h = 0.01;
  std::vector<core::Box2> regions;
  const int n = comm.size();
  for (int r = 0; r < n; ++r) regions.push_back({{L * r / n, 0.0}, {L * (r + 1) / n, H}});
  dem::DemSolver dem(comm, cfg, regions, {{0.0, 0.0}, {L, H}}, {});
  std::vector<dem::SolidSpec> specs;
  const std::int64_t ids[] = {5, 2, 8, 0, 3};
  for (int s = 0; s < 5; ++s) {
    dem::SolidSpec spec;
    spec.shape = std::make_shared<const geometry::Circle>(0.02);
    spec.density = 1000.0;
    spec.state.id = ids[s];
    // near every strip border: x = k/n +- 0.03
    const int strip = s % n;
    spec.state.x = {L * (strip + 0.5) / n + (s % 2 ? -1.0 : 1.0) * (0.5 * L / n - 0.03),
                    0.1 + 0.06 * s};
    spec.state.v = {0.1 * s, 0.0};
    specs.push_back(spec);
  }
  dem.add_solids(specs);
  const auto scene = coupling::scene_of(&dem, {});
  const std::size_t seen = dem.owned().size() + dem.ghosts().size();
  ASSERT_EQ(scene.states.size(), seen);
  ASSERT_EQ(scene.placements.size(), seen);
  if (n == 1) {
    EXPECT_EQ(seen, 5u);
  }
  for (std::size_t b = 0; b < seen; ++b) {
    if (b > 0) {
      EXPECT_LT(scene.states[b - 1].id, scene.states[b].id);
    }
    EXPECT_EQ(scene.placements[b].id, scene.states[b].id);
    EXPECT_EQ(scene.placements[b].pose.x.x, scene.states[b].x.x);
    EXPECT_EQ(scene.placements[b].pose.x.z, scene.states[b].x.z);
    EXPECT_EQ(scene.index_of(scene.states[b].id), static_cast<int>(b));
    EXPECT_NEAR(scene.placements[b].shape->bounding_radius(), 0.02, 1e-15);
  }
}

// Open tank sides (open_boundary.hpp, open_flow.hpp, doc/open_boundaries.md): the inflow
// profiles and their time integrals, the key checks, the boundary velocities and ghosts, the
// pressure rows of inflow and outflow faces, a projection through an open channel, and the
// viscous stencil's legs at open sides.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "fluid_test_support.hpp"
#include "picdem/core/error.hpp"
#include "picdem/fluid/open_flow.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/fluid/viscous.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

using fluid_test::kAir;
using fluid_test::kFluid;

/// Every cell of the grid fluid, the cells beyond the tank air (no particle ever reaches them:
/// what mark_cells makes of them).
fluid::CellStates fluid_inside_air_outside(const Decomposition& d) {
  fluid::CellStates c(d, Stagger::Cell, kAir);
  const auto& b = c.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && k >= 0 && i < d.spec().nx && k < d.spec().nz) c(i, k) = kFluid;
  return c;
}

std::string error_of(const std::vector<std::string>& overrides) {
  try {
    fluid_test::tank_params(0.4, 0.2, 0.05, overrides);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OpenBoundary, ProfilesAndTheirTimeIntegrals) {
  fluid::OpenSide s;
  s.kind = fluid::OpenKind::Inflow;
  s.from = 0.1, s.to = 0.5;
  s.shape = fluid::InflowShape::Parabolic, s.velocity = 0.3;
  // u = 4 U (s - a)(b - s) / (b - a)^2
  EXPECT_DOUBLE_EQ(s.speed(0.3, 7.0), 0.3);
  EXPECT_NEAR(s.speed(0.2, 0.0), 4 * 0.3 * 0.1 * 0.3 / 0.16, 1e-15);
  EXPECT_EQ(s.speed(0.1, 0.0), 0.0);
  EXPECT_NEAR(s.displacement(0.2, 2.0), 2.0 * s.speed(0.2, 0.0), 1e-15);
  const auto b = s.displacement_bounds(0.25, 0.35, 2.0);  // holds the vertex
  EXPECT_NEAR(b[1], 0.6, 1e-15);
  EXPECT_NEAR(b[0], 2.0 * s.speed(0.25, 0.0), 1e-15);
  // A table over two heights and three times, constant beyond the ends: its displacement
  // against a fine midpoint sum of its speed.
  s.shape = fluid::InflowShape::Table;
  s.heights = {0.0, 0.2}, s.times = {0.5, 1.0, 2.0};
  s.table = {0.1, 0.3, 0.2, 0.2, 0.0, 0.4};
  EXPECT_NEAR(s.speed(0.1, 0.75), 0.5 * (0.2 + 0.2), 1e-15);
  EXPECT_NEAR(s.speed(0.1, 9.0), 0.2, 1e-15);
  for (double t : {0.3, 0.8, 1.7, 3.0}) {
    const int n = 300000;
    double sum = 0.0;
    for (int m = 0; m < n; ++m) sum += s.speed(0.05, (m + 0.5) * t / n) * t / n;
    EXPECT_NEAR(s.displacement(0.05, t), sum, 1e-9) << t;
  }
  fluid::OpenBoundaries o;
  o.side[0] = s;
  o.t0 = 0.8, o.t1 = 1.3;
  EXPECT_NEAR(o.face_speed(0, 0.05), (s.displacement(0.05, 1.3) - s.displacement(0.05, 0.8)) / 0.5,
              1e-15);
}

TEST(OpenBoundary, KeyChecksNameKeyValueAndReason) {
  EXPECT_NE(error_of({"open/left/type=inflow"}).find("'open/left/velocity' = 0"),
            std::string::npos);
  EXPECT_NE(error_of({"open/right/velocity=0.3"}).find("'open/right/type' is wall"),
            std::string::npos);
  EXPECT_NE(error_of({"open/top/type=outflow", "open/top/range=[0.1, 0.5]"})
                .find("'open/top/range' must be empty or [from, to] with 0 <= from < to <= 0.4"),
            std::string::npos);
  EXPECT_NE(error_of({"open/left/type=inflow", "open/left/profile=table",
                      "open/left/heights=[0, 0.1]", "open/left/times=[0]", "open/left/table=[0.1]"})
                .find("len(heights) x len(times) speeds (got 2, 1, 1)"),
            std::string::npos);
  EXPECT_NE(error_of({"open/bottom/type=sink"}).find("open/bottom/type"), std::string::npos);
  EXPECT_NE(error_of({"open/left/type=inflow", "open/left/velocity=0.2",
                      "open/left/outflow_velocity=zero_gradient"})
                .find("'open/left/outflow_velocity' belongs to an outflow, but 'open/left/type' "
                      "is inflow"),
            std::string::npos);
  EXPECT_EQ(error_of({"open/left/type=inflow", "open/left/velocity=0.2", "open/right/type=outflow",
                      "open/right/range=[0.05, 0.15]"}),
            "");
}

// An inflow on the left over z in [0.05, 0.15] (faces k = 1, 2 of h = 0.05), an outflow on the
// whole right side.
TEST(OpenBoundary, WallVelocitiesAndGhostsOfOpenSides) {
  core::Comm self(MPI_COMM_SELF);
  const auto params = fluid_test::tank_params(
      0.4, 0.2, 0.05,
      {"fluid/walls=no_slip", "open/left/type=inflow", "open/left/velocity=0.2",
       "open/left/range=[0.05, 0.15]", "open/right/type=outflow"});
  const auto cfg = fluid::config_from(params);
  GridSpec s = spec_from(params);
  Decomposition d(s, self, 2);
  FaceField u(d, Stagger::FaceX, 0.7), w(d, Stagger::FaceZ, 0.0);
  for (int k = -2; k < 6; ++k)
    for (int i = -2; i < 10; ++i) w(i, k) = 0.01 * i + 0.1 * k;
  u(8, 1) = 0.31;  // an outflow face's value is kept
  fluid::enforce_walls(u, w, cfg, d);
  EXPECT_EQ(u(0, 0), 0.0);  // wall below the inflow range
  EXPECT_EQ(u(0, 3), 0.0);  // and above it
  for (int k : {1, 2}) {
    EXPECT_DOUBLE_EQ(u(0, k), 0.2);
    EXPECT_DOUBLE_EQ(u(-1, k), 0.2);  // ghosts: the inflow
    EXPECT_DOUBLE_EQ(u(-2, k), 0.2);
  }
  EXPECT_EQ(u(8, 1), 0.31);
  EXPECT_EQ(u(9, 1), 0.31);  // zero normal gradient beyond the outflow
  EXPECT_EQ(u(10, 1), 0.31);
  EXPECT_EQ(u(8, 0), 0.7);
  // tangential ghosts: -mirror at the inflow (w = 0 on the side), +mirror at the outflow; the
  // no-slip wall elsewhere: -mirror
  EXPECT_DOUBLE_EQ(w(-1, 2), -w(0, 2));
  EXPECT_DOUBLE_EQ(w(-1, 0), -w(0, 0));
  EXPECT_DOUBLE_EQ(w(8, 2), w(7, 2));
  EXPECT_DOUBLE_EQ(w(9, 1), w(6, 1));
  // apertures: open faces get E = h, the rest of the sides stay closed
  auto E = fluid::open_apertures(d);
  fluid::open_side_apertures(E, cfg.open, d);
  EXPECT_EQ(E.E_x(0, 0), 0.0);
  EXPECT_EQ(E.E_x(0, 1), 0.05);
  EXPECT_EQ(E.E_x(0, 3), 0.0);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(E.E_x(8, k), 0.05);
  EXPECT_EQ(E.E_z(3, 0), 0.0);
  // fluxes: in through two faces, out through four
  auto cells = fluid_inside_air_outside(d);
  const auto q = fluid::open_fluxes(u, w, cells, nullptr, cfg.open, d, self);
  EXPECT_NEAR(q.inflow, 2 * 0.05 * 0.2, 1e-15);
  EXPECT_NEAR(q.outflow, 0.05 * (0.31 + 3 * 0.7), 1e-15);
  // Water below z = 0.1 only: the outflow faces beside the two air cells at the right side (k =
  // 2, 3) carry the air's velocity and move no water; the inflow's faces count whatever is inside
  // (its particles are injected into them).
  for (int k = 2; k < 4; ++k)
    for (int i = 0; i < 8; ++i) cells(i, k) = kAir;
  const auto q_air = fluid::open_fluxes(u, w, cells, nullptr, cfg.open, d, self);
  EXPECT_NEAR(q_air.inflow, 2 * 0.05 * 0.2, 1e-15);
  EXPECT_NEAR(q_air.outflow, 0.05 * (0.31 + 0.7), 1e-15);
  // With the sub-cell surface 0.3 h above the centre of the top fluid cell at the outflow (the
  // face between cells (7, 1) and (7, 2)), that cell's outflow face is wet over h/2 + 0.3 h; the
  // bottom cell's face is whole (the floor below it is a wall, not a surface).
  fluid::SurfaceFractions surface{FaceField(d, Stagger::FaceX, 1.0),
                                  FaceField(d, Stagger::FaceZ, 1.0)};
  surface.theta_z(7, 2) = 0.3;
  surface.theta_z(7, 0) = 0.2;  // the floor's face: not a surface, never read
  const auto q_wet = fluid::open_fluxes(u, w, cells, &surface, cfg.open, d, self);
  EXPECT_NEAR(q_wet.inflow, 2 * 0.05 * 0.2, 1e-15);
  EXPECT_NEAR(q_wet.outflow, 0.05 * (0.8 * 0.31 + 0.7), 1e-15);
}

// open/right/outflow_velocity: zero_gradient over z in [0.05, 0.15] (faces k = 1, 2 of h = 0.05):
// those outflow faces take the interior faces' velocity (du_n / dn = 0), and enforce_walls then
// keeps it and copies it into the ghosts; the right side's other faces and a projected outflow on
// the top keep their own values.
TEST(OpenBoundary, ZeroGradientOutflowTakesTheInteriorFace) {
  core::Comm self(MPI_COMM_SELF);
  const auto params = fluid_test::tank_params(
      0.4, 0.2, 0.05,
      {"open/right/type=outflow", "open/right/range=[0.05, 0.15]",
       "open/right/outflow_velocity=zero_gradient", "open/top/type=outflow"});
  const auto cfg = fluid::config_from(params);
  EXPECT_TRUE(cfg.open.side[1].zero_gradient);
  EXPECT_FALSE(cfg.open.side[3].zero_gradient);
  GridSpec s = spec_from(params);
  Decomposition d(s, self, 2);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (int k = -2; k < 6; ++k)
    for (int i = -2; i < 11; ++i) u(i, k) = 0.01 * i + 0.1 * k;
  for (int k = -2; k < 7; ++k)
    for (int i = -2; i < 10; ++i) w(i, k) = 0.02 * i + 0.3 * k;
  fluid::zero_gradient_outflow(u, w, cfg.open, d);
  fluid::enforce_walls(u, w, cfg, d);
  for (int k : {1, 2}) {
    EXPECT_DOUBLE_EQ(u(8, k), 0.07 + 0.1 * k);  // u(7, k)
    EXPECT_DOUBLE_EQ(u(9, k), 0.07 + 0.1 * k);  // the ghost beyond
  }
  EXPECT_EQ(u(8, 0), 0.0);  // the wall below the range
  EXPECT_EQ(u(8, 3), 0.0);  // and above it
  for (int i = 0; i < 8; ++i) EXPECT_DOUBLE_EQ(w(i, 4), 0.02 * i + 1.2);  // projected: kept
}

// 4 x 4 fluid cells, h = 0.1, rho = 1000, dt = 0.01 (dt/(rho h) E = 1e-5): an inflow on the left
// adds no matrix term and its flux to the right-hand side; an outflow on the right adds E dt /
// (rho h theta) to the diagonal: theta = 1 (p = 0 at the ghost's centre) without the ghost fluid,
// 1/2 (p = 0 on the face) with it.
TEST(OpenBoundary, PressureRowsOfInflowAndOutflowFaces) {
  core::Comm world;
  if (world.rank() != 0) return;
  core::Comm self(MPI_COMM_SELF);
  const auto params = fluid_test::tank_params(
      0.4, 0.4, 0.1,
      {"open/left/type=inflow", "open/left/velocity=0.2", "open/right/type=outflow"});
  auto cfg = fluid::config_from(params);
  cfg.open.t0 = 0.0, cfg.open.t1 = 0.01;
  GridSpec s = spec_from(params);
  Decomposition d(s, self, 1);
  const auto cells = fluid_inside_air_outside(d);
  auto E = fluid::open_apertures(d);
  fluid::open_side_apertures(E, cfg.open, d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  fluid::enforce_walls(u, w, cfg, d);
  fluid::PressureSolver solver(d, params);
  fluid::SurfaceFractions surface{FaceField(d, Stagger::FaceX, 1.0),
                                  FaceField(d, Stagger::FaceZ, 1.0)};
  for (int with_surface = 0; with_surface < 2; ++with_surface) {
    if (with_surface) fluid::open_surface_fractions(surface, cfg.open, d);
    const auto sys = solver.assemble(cells, E, u, w, {}, 0.01, cfg, &surface);
    ASSERT_EQ(sys.rows.size(), 16u);
    const double outflow = with_surface ? 2e-5 : 1e-5;
    for (std::size_t r = 0; r < 16; ++r) {
      const long long id = sys.rows[r];
      const int i = static_cast<int>(id % 4), k = static_cast<int>(id / 4);
      std::map<long long, double> row(sys.entries[r].begin(), sys.entries[r].end());
      // 1e-5 per fluid neighbour, plus the outflow face
      const int neighbours = (i > 0) + (i < 3) + (k > 0) + (k < 3);
      const double diag = 1e-5 * neighbours + (i == 3 ? outflow : 0.0);
      EXPECT_NEAR(row[id], diag, 1e-20) << "cell " << id;
      // b = -D = E u_in on the inflow cells
      EXPECT_NEAR(sys.rhs[r], i == 0 ? 0.1 * 0.2 : 0.0, 1e-16) << "cell " << id;
    }
  }
}

// Potential flow through a channel of 6 x 4 fluid cells: an inflow of 0.2 m/s over the whole left
// side, an outflow (p = 0 on its faces) on the right, u~ = 0 inside: the projection gives u = 0.2
// on every x-face and w = 0, and p falls linearly to 0 at the outflow face,
// p_i = rho U h (nx - i - 1/2) / dt.
TEST(OpenBoundary, ProjectionThroughAnOpenChannel) {
  core::Comm world;
  if (world.rank() != 0) return;
  core::Comm self(MPI_COMM_SELF);
  const auto params =
      fluid_test::tank_params(0.6, 0.4, 0.1,
                              {"open/left/type=inflow", "open/left/velocity=0.2",
                               "open/right/type=outflow", "solver/tolerance=1e-12"});
  const auto cfg = fluid::config_from(params);
  GridSpec s = spec_from(params);
  Decomposition d(s, self, 1);
  const auto cells = fluid_inside_air_outside(d);
  auto E = fluid::open_apertures(d);
  fluid::open_side_apertures(E, cfg.open, d);
  fluid::SurfaceFractions surface{FaceField(d, Stagger::FaceX, 1.0),
                                  FaceField(d, Stagger::FaceZ, 1.0)};
  fluid::open_surface_fractions(surface, cfg.open, d);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  fluid::enforce_walls(u, w, cfg, d);
  CellField p(d, Stagger::Cell, 0.0);
  fluid::PressureSolver solver(d, params);
  const double dt = 0.01;
  solver.solve(cells, E, u, w, {}, dt, cfg, p, &surface);
  fluid::project(u, w, p, cells, E, dt, cfg, &surface);
  fluid::enforce_walls(u, w, cfg, d);
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i <= 6; ++i) EXPECT_NEAR(u(i, k), 0.2, 1e-10) << i << " " << k;
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(p(i, k), 1000.0 * 0.2 * 0.1 * (6 - i - 0.5) / dt, 1e-6) << i << " " << k;
  }
  for (int k = 0; k <= 4; ++k)
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(w(i, k), 0.0, 1e-10);
  const auto q = fluid::open_fluxes(u, w, cells, nullptr, cfg.open, d, self);
  EXPECT_NEAR(q.inflow, 0.4 * 0.2, 1e-14);
  EXPECT_NEAR(q.outflow, 0.4 * 0.2, 1e-10);
}

// The implicit viscous stencil on a 4 x 4 grid (h = 1) with an inflow on the left and an outflow
// on the right: the u nodes next to the inflow have a leg to it (theta = 1) with the inflow
// speed; the w nodes next to it a leg half a cell away with value 0 (no tangential velocity);
// next to the outflow there is no leg (do-nothing), for u and w.
TEST(OpenBoundary, ViscousLegsAtOpenSides) {
  core::Comm self(MPI_COMM_SELF);
  auto params = fluid_test::tank_params(4.0, 4.0, 1.0,
                                        {"fluid/walls=no_slip", "open/left/type=inflow",
                                         "open/left/velocity=0.5", "open/right/type=outflow"});
  const auto cfg = fluid::config_from(params);
  const fluid::ViscousWalls walls = fluid::viscous_walls_of(cfg);
  const fluid::ViscousGrid g{{0.0, 0.0}, 1.0, 4, 4};
  for (int component : {0, 1}) {
    const auto st = fluid::build_viscous_stencil(component, g, {}, walls);
    int inflow_legs = 0, outflow_side = 0;
    for (const auto& leg : st.legs) {
      const double x = leg.point.x;
      if (x == 0.0) {
        ++inflow_legs;
        EXPECT_DOUBLE_EQ(leg.value, component == 0 ? 0.5 : 0.0);
        EXPECT_DOUBLE_EQ(leg.weight, component == 0 ? 1.0 : 2.0);
      }
      if (x == 4.0) ++outflow_side;
    }
    EXPECT_EQ(inflow_legs, component == 0 ? 4 : 3);  // one per node next to the side
    EXPECT_EQ(outflow_side, 0);
  }
}

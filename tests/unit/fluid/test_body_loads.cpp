// The solids' rows of the pressure equation (fluid/body_loads.hpp) against values worked by hand
// (rows a_{s,c}, quadrature load F_q, predicted velocity V*, eq. 6), and the fluid loads on
// solids, J_s p + F_q (eq. 6 with the quadrature load), from the coupling rows
// a_{s,c} that the pressure matrix is assembled from, against an independent boundary integral:
// in a linear, non-hydrostatic pressure field p = p0 + a x + b z the exact load on a closed body
// is F = -int p n dl = -A (a, b) (divergence theorem) and the torque about the centre of mass is
// -int p (r x n) dl = -(b int r_x dA - a int r_z dA) = 0. J p takes one value p_c per cell; the
// quadrature load carries p from x_c along grad p over each piece with the exact first moments
// of the wetted pieces, so the two together are the exact integral up to rounding. That holds with
// tiny_fraction = 0; with the default tiny-cell rule each dropped cell's fluid (below 1e-3 h^2)
// joins the body, whose load then grows by at most that area times |grad p|.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include "picdem/fluid/bodies.hpp"
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

// The cut cells of the bodies over this rank's storage window; E = min(tank, cut cells) (as the
// step's geometry phase).
geometry::CutCells cut_cells(const std::vector<geometry::SolidPlacement>& placements,
                             const grid::Decomposition& d, double tiny_fraction,
                             fluid::Apertures& E) {
  const auto& spec = d.spec();
  geometry::CutCellOptions options;
  options.tiny_fraction = tiny_fraction;
  auto cut = geometry::build_cut_cells({spec.origin, spec.h, d.storage(grid::Stagger::Cell)},
                                       placements, {}, options);
  E = fluid::body_apertures(cut, d);
  return cut;
}

struct Body {
  geometry::ShapePtr shape;
  geometry::Pose pose;
  double area = 0.0, radius = 0.0;
};

core::Params case_params() {
  core::ParamSchema schema;
  grid::declare_parameters(schema);
  fluid::declare_parameters(schema);
  return core::read_case_text("grid: {length: 1.0, height: 1.0, cell_size: 0.01}\n", "loads test",
                              {}, schema);
}

// J_s p + F_q as the step computes them: the solver assembles the rows (with the apertures E and
// zero face velocities; the loads do not depend on either) and returns the loads from them.
std::vector<core::SolidLoads> solver_loads(fluid::PressureSolver& solver,
                                           const core::Params& params, const grid::Decomposition& d,
                                           const fluid::CellStates& cells,
                                           const fluid::Apertures& E,
                                           const std::vector<fluid::SolidCoupling>& rows,
                                           const grid::CellField& p) {
  grid::FaceField u(d, grid::Stagger::FaceX, 0.0), w(d, grid::Stagger::FaceZ, 0.0);
  solver.assemble(cells, E, u, w, rows, 1e-3, fluid::config_from(params));
  return solver.solid_loads(p);
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
  const std::vector<geometry::SolidPlacement> placements = {
      {7, std::make_shared<geometry::Polygon>(verts), {{0.3, 0.35}, 0.0}}};
  core::SolidState st;
  st.id = 7, st.x = {0.3, 0.35}, st.v = {0.1, -0.2}, st.omega = 0.5;
  st.mass = 20.0, st.inertia = 0.1;
  const std::vector<core::SolidState> states = {st};
  fluid::Apertures E;
  const auto cut = cut_cells(placements, d, 0.0, E);
  fluid::CellStates cells(d, grid::Stagger::Cell, kFluid);
  cells(3, 4) = kAir;
  const std::vector<core::SolidLoads> collision = {{7, {3.0, -4.0}, 0.02}};
  const fluid::QuadratureOptions q{true, 1000.0, {0.0, -9.81}};
  const double dt = 1e-3;
  const auto out = fluid::solid_couplings(states, cut, cells, d, collision, q, dt);
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
  const auto plain = fluid::solid_couplings(states, cut, cells, d, collision, one_point, dt);
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_EQ(plain[0].load[0], 0.0);
  EXPECT_EQ(plain[0].load[2], 0.0);
  EXPECT_NEAR(plain[0].v_star[0], 0.1 + dt * 3.0 / 20.0, 1e-15);
  EXPECT_NEAR(plain[0].v_star[2], 0.5 + dt * 0.02 / 0.1, 1e-15);
}

TEST(SolidLoads, LinearPressureFieldOnDiskAndPolygonIsTheExactIntegral) {
  core::Comm comm;
  const auto params = case_params();
  const grid::GridSpec s = grid::spec_from(params);
  grid::Decomposition d(s, comm, fluid::required_halo());
  // A disk of 20 cells per diameter and an irregular pentagon, rotated, off the grid lines.
  std::vector<Body> bodies;
  bodies.push_back(
      {std::make_shared<geometry::Circle>(0.1), {{0.4137, 0.5291}, 0.3}, M_PI * 0.01, 0.1});
  const std::vector<Vec2> verts = {
      {-0.09, -0.06}, {0.1, -0.08}, {0.13, 0.05}, {0.0, 0.12}, {-0.1, 0.04}};
  const auto poly = std::make_shared<geometry::Polygon>(verts);
  const double theta = 0.7;
  bodies.push_back({poly,
                    {Vec2{0.7, 0.3} + core::rotate(poly->centroid_offset(), theta), theta},
                    geometry::polygon_properties(verts).area,
                    poly->bounding_radius()});
  std::vector<geometry::SolidPlacement> placements;
  std::vector<core::SolidState> states;
  for (std::size_t n = 0; n < bodies.size(); ++n) {
    placements.push_back({static_cast<std::int64_t>(n), bodies[n].shape, bodies[n].pose});
    core::SolidState st;
    st.id = static_cast<std::int64_t>(n), st.x = bodies[n].pose.x, st.theta = bodies[n].pose.theta;
    st.mass = 1000.0 * bodies[n].area, st.inertia = 10.0 * bodies[n].area;
    states.push_back(st);
  }
  fluid::Apertures E;
  const auto cut = cut_cells(placements, d, 0.0, E);
  fluid::Apertures E_tiny;
  const auto cut_tiny = cut_cells(placements, d, 1e-3, E_tiny);
  // Every cell fluid (the loads read only the cut cells), p linear at the cell centres.
  const double p0 = 2000.0, a = 1234.5, b = -8765.4;
  fluid::CellStates cells(d, grid::Stagger::Cell, static_cast<signed char>(grid::CellState::Fluid));
  grid::CellField p(d, grid::Stagger::Cell, 0.0);
  const auto box = p.storage();
  for (int k = box.k0; k < box.k1; ++k)
    for (int i = box.i0; i < box.i1; ++i) {
      const Vec2 x = s.position(grid::Stagger::Cell, i, k);
      p(i, k) = p0 + a * x.x + b * x.z;
    }
  // The quadrature carries p along grad p = rho g: rho = 1, g = (a, b).
  const fluid::QuadratureOptions full{true, 1.0, {a, b}}, one_point{false, 1.0, {a, b}};
  fluid::PressureSolver solver(d, params);
  const auto rows = fluid::solid_couplings(states, cut, cells, d, {}, full, 1e-3);
  const auto loads = solver_loads(solver, params, d, cells, E, rows, p);
  const auto rows1 = fluid::solid_couplings(states, cut, cells, d, {}, one_point, 1e-3);
  const auto loads1 = solver_loads(solver, params, d, cells, E, rows1, p);
  ASSERT_EQ(loads.size(), 2u);
  ASSERT_EQ(loads1.size(), 2u);
  for (std::size_t n = 0; n < 2; ++n) {
    const Vec2 exact = -bodies[n].area * Vec2{a, b};
    const double scale = std::hypot(exact.x, exact.z);
    EXPECT_EQ(loads[n].id, static_cast<std::int64_t>(n));
    EXPECT_NEAR(loads[n].force.x, exact.x, 1e-12 * scale) << "body " << n;
    EXPECT_NEAR(loads[n].force.z, exact.z, 1e-12 * scale) << "body " << n;
    EXPECT_NEAR(loads[n].torque, 0.0, 1e-12 * scale * bodies[n].radius) << "body " << n;
    // The one-point rule alone (p_c over the whole piece) is off by far more than that.
    const double err1 = std::hypot(loads1[n].force.x - exact.x, loads1[n].force.z - exact.z);
    EXPECT_GT(err1 / scale, 1e-5) << "body " << n;
    if (comm.is_root())
      std::printf("body %zu: |J p + F_q - F| / |F| = %.1e, torque %.1e N; one-point rule %.1e\n", n,
                  std::hypot(loads[n].force.x - exact.x, loads[n].force.z - exact.z) / scale,
                  loads[n].torque, err1 / scale);
  }

  // The default tiny-cell rule: within the dropped cells' area (at most 1e-3 h^2 each).
  const auto own = d.owned_cells();
  long long dropped = 0;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) dropped += cut_tiny.dropped(i, k) ? 1 : 0;
  dropped = comm.sum(dropped);
  EXPECT_GT(dropped, 0);
  const auto loads_tiny =
      solver_loads(solver, params, d, cells, E_tiny,
                   fluid::solid_couplings(states, cut_tiny, cells, d, {}, full, 1e-3), p);
  for (std::size_t n = 0; n < 2; ++n) {
    const Vec2 exact = -bodies[n].area * Vec2{a, b};
    const double bound = std::hypot(a, b) * static_cast<double>(dropped) * 1e-3 * s.h * s.h;
    EXPECT_LE(std::hypot(loads_tiny[n].force.x - exact.x, loads_tiny[n].force.z - exact.z),
              bound * (1.0 + 1e-9))
        << "body " << n;
  }
}

// The fluid loads on solids, J_s p + F_q (eq. 6 with the quadrature load), from the coupling rows
// a_{s,c} that the pressure matrix is assembled from, against an independent boundary integral:
// in a linear, non-hydrostatic pressure field p = p0 + a x + b z the exact load on a closed body
// is F = -int p n dl = -A (a, b) (divergence theorem) and the torque about the centre of mass is
// -int p (r x n) dl = -(b int r_x dA - a int r_z dA) = 0. J p takes one value p_c per cell; the
// quadrature load carries p from x_c along grad p over each piece with the exact first moments
// of the wetted pieces, so the two together are the exact integral up to rounding. That holds with
// tiny_fraction = 0; with the default tiny-cell rule each dropped cell's fluid (below 1e-3 h^2)
// joins the body, whose load then grows by at most that area times |grad p|.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/fluid/body_loads.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem;
using core::Vec2;

namespace {

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

}  // namespace

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
  coupling::SolidScene scene;
  for (std::size_t n = 0; n < bodies.size(); ++n) {
    scene.placements.push_back({static_cast<std::int64_t>(n), bodies[n].shape, bodies[n].pose});
    core::SolidState st;
    st.id = static_cast<std::int64_t>(n), st.x = bodies[n].pose.x, st.theta = bodies[n].pose.theta;
    st.mass = 1000.0 * bodies[n].area, st.inertia = 10.0 * bodies[n].area;
    scene.states.push_back(st);
  }
  fluid::Apertures E;
  const auto cut = coupling::cut_cells(scene, d, 0.0, E);
  fluid::Apertures E_tiny;
  const auto cut_tiny = coupling::cut_cells(scene, d, 1e-3, E_tiny);
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
  const auto rows = fluid::solid_couplings(scene.states, cut, cells, d, {}, full, 1e-3);
  const auto loads = fluid::pressure_loads(rows, p, cells, d);
  const auto rows1 = fluid::solid_couplings(scene.states, cut, cells, d, {}, one_point, 1e-3);
  const auto loads1 = fluid::pressure_loads(rows1, p, cells, d);
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
  const auto loads_tiny = fluid::pressure_loads(
      fluid::solid_couplings(scene.states, cut_tiny, cells, d, {}, full, 1e-3), p, cells, d);
  for (std::size_t n = 0; n < 2; ++n) {
    const Vec2 exact = -bodies[n].area * Vec2{a, b};
    const double bound = std::hypot(a, b) * static_cast<double>(dropped) * 1e-3 * s.h * s.h;
    EXPECT_LE(std::hypot(loads_tiny[n].force.x - exact.x, loads_tiny[n].force.z - exact.z),
              bound * (1.0 + 1e-9))
        << "body " << n;
  }

  // The pressure solver's loads come from the rows it assembled, and equal these bitwise.
  fluid::PressureSolver solver(d, params);
  grid::FaceField u(d, grid::Stagger::FaceX, 0.0), w(d, grid::Stagger::FaceZ, 0.0);
  solver.assemble(cells, E, u, w, rows, 1e-3, fluid::config_from(params));
  const auto from_solver = solver.solid_loads(p);
  ASSERT_EQ(from_solver.size(), 2u);
  for (std::size_t n = 0; n < 2; ++n) {
    EXPECT_EQ(from_solver[n].force.x, loads[n].force.x);
    EXPECT_EQ(from_solver[n].force.z, loads[n].force.z);
    EXPECT_EQ(from_solver[n].torque, loads[n].torque);
  }
}

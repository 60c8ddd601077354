// The source of the density correction (fluid/free_surface.hpp, doc/coupling.md) against values
// worked by hand: relaxation (S - 1) f h^2, capped; a deficit (S < 1) only where the 3x3 block
// holds no air (at the surface S < 1 is the surface); weighted by the fluid fraction of a cut cell.
#include <gtest/gtest.h>

#include "picdem/fluid/bodies.hpp"
#include "picdem/fluid/free_surface.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

constexpr signed char kAir = static_cast<signed char>(CellState::Air);
constexpr signed char kFluid = static_cast<signed char>(CellState::Fluid);

// 6 x 6 cells of h = 0.1 on one rank; rows k = 0..3 fluid, 4 and 5 air.
struct Tank {
  GridSpec spec;
  std::unique_ptr<Decomposition> d;
  fluid::CellStates cells;
  CellField S;
  Tank() {
    spec.nx = 6, spec.nz = 6, spec.h = 0.1;
    d = std::make_unique<Decomposition>(spec, core::Comm(MPI_COMM_SELF), 1);
    cells = fluid::CellStates(*d, Stagger::Cell, kAir);
    S = CellField(*d, Stagger::Cell, 0.0);
    const auto b = cells.storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i)
        if (k >= 0 && k <= 3) cells(i, k) = kFluid, S(i, k) = 1.0;
  }
};

}  // namespace

TEST(ExcessArea, UniformDensityHasNoSource) {
  Tank t;
  CellField source(*t.d, Stagger::Cell, 1.0);
  EXPECT_FALSE(fluid::excess_area(t.S, t.cells, nullptr, 0.5, 0.5, *t.d, source));
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 6; ++i) EXPECT_EQ(source(i, k), 0.0) << i << " " << k;
}

TEST(ExcessArea, CappedAndNoDeficitAtTheSurface) {
  Tank t;
  t.S(2, 1) = 1.4;  // crowded
  t.S(3, 1) = 0.7;  // thinned, inside: a deficit
  t.S(4, 2) = 2.5;  // capped at 1 + 0.5
  t.S(0, 0) = 1.2;  // in the corner: the walls are not air
  t.S(2, 3) = 1.2;  // row 3 touches the air of row 4: crowded all the same
  t.S(1, 3) = 0.4;  // the surface, not a deficit
  CellField source(*t.d, Stagger::Cell, 0.0);
  ASSERT_TRUE(fluid::excess_area(t.S, t.cells, nullptr, 0.5, 0.5, *t.d, source));
  const double a = 0.1 * 0.1;
  EXPECT_NEAR(source(2, 1), 0.5 * 0.4 * a, 1e-15);
  EXPECT_NEAR(source(3, 1), -0.5 * 0.3 * a, 1e-15);
  EXPECT_NEAR(source(4, 2), 0.5 * 0.5 * a, 1e-15);
  EXPECT_NEAR(source(0, 0), 0.5 * 0.2 * a, 1e-15);
  EXPECT_NEAR(source(2, 3), 0.5 * 0.2 * a, 1e-15);
  EXPECT_EQ(source(1, 3), 0.0);
  EXPECT_EQ(source(2, 4), 0.0);  // air
}

TEST(ExcessArea, CutCellWeightedByItsFluidFraction) {
  Tank t;
  // An obstacle covering the left half of cell (2, 1): fluid fraction 1/2.
  std::vector<geometry::Obstacle> obstacles;
  obstacles.push_back({"block", {{{0.2, 0.1}, {0.25, 0.1}, {0.25, 0.2}, {0.2, 0.2}}}});
  fluid::Apertures E = fluid::open_apertures(*t.d);
  const auto cut = fluid::cut_cells({}, obstacles, 1e-3, *t.d, E);
  ASSERT_NEAR(cut.fluid_fraction(2, 1), 0.5, 1e-12);
  t.S(2, 1) = 1.4;
  CellField source(*t.d, Stagger::Cell, 0.0);
  ASSERT_TRUE(fluid::excess_area(t.S, t.cells, &cut, 1.0, 0.5, *t.d, source));
  EXPECT_NEAR(source(2, 1), 0.4 * 0.5 * 0.01, 1e-15);
}

// The coupling phases against values worked by hand: the damping of particles in contact gaps
// (eq. 20) and the solids' snapshot (ordered by id, matched by id across the DEM; every solid of
// the run on every rank for the implicit viscous solve). The solid
// couplings of the pressure equation are the fluid's: tests/unit/fluid/test_body_loads.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "picdem/coupling/solids_in_fluid.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/dem/scene.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/grid/field.hpp"
#include "step_phases.hpp"  // private to the coupling module: place_solids, CutCellsAhead

using namespace picdem;
using core::Vec2;

namespace {

core::SolidState state(std::int64_t id, Vec2 x, Vec2 v = {}, double omega = 0.0) {
  core::SolidState st;
  st.id = id, st.x = x, st.v = v, st.omega = omega;
  return st;
}

// A DEM over a 1 m x 0.5 m tank cut into one strip per rank, holding disks of density 1000 with
// the ids `ids`; solid s has radius radius(s), centre at(s) and velocity v(s).
template <class Radius, class At, class Velocity>
std::unique_ptr<dem::DemSolver> strip_dem(const core::Comm& comm,
                                          const std::vector<std::int64_t>& ids, Radius radius,
                                          At at, Velocity v) {
  const double L = 1.0, H = 0.5;
  dem::DemConfig cfg;
  cfg.h = 0.01;
  std::vector<core::Box2> regions;
  const int n = comm.size();
  for (int r = 0; r < n; ++r) regions.push_back({{L * r / n, 0.0}, {L * (r + 1) / n, H}});
  auto dem = std::make_unique<dem::DemSolver>(comm, cfg, regions, core::Box2{{0.0, 0.0}, {L, H}},
                                              std::vector<std::vector<Vec2>>{});
  std::vector<dem::SolidSpec> specs;
  for (int s = 0; s < static_cast<int>(ids.size()); ++s) {
    dem::SolidSpec spec;
    spec.shape = std::make_shared<const geometry::Circle>(radius(s));
    spec.density = 1000.0;
    spec.state.id = ids[static_cast<std::size_t>(s)];
    spec.state.x = at(s);
    spec.state.v = v(s);
    specs.push_back(spec);
  }
  dem->add_solids(specs);
  return dem;
}

}  // namespace

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
  dem::SolidScene before, after;
  before.states = {state(3, {0.1, 0.1}, {1.0, 0.0}), state(7, {0.2, 0.2}, {2.0, 0.0}),
                   state(9, {0.3, 0.3}, {3.0, 0.0})};
  after.states = {state(7, {0.25, 0.2}, {-2.0, 0.5}, 1.5), state(9, {0.3, 0.35}, {0.0, 3.0}),
                  state(12, {0.9, 0.9}, {4.0, 4.0})};
  EXPECT_EQ(after.index_of(7), 0);
  EXPECT_EQ(after.index_of(12), 2);
  EXPECT_EQ(after.index_of(3), -1);
  EXPECT_EQ(before.index_of(3), 0);
  EXPECT_EQ(before.index_of(8), -1);
  const auto m = dem::motions_at(before, after);
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
  const double L = 1.0;
  const int n = comm.size();
  const auto dem_ptr = strip_dem(
      comm, {5, 2, 8, 0, 3}, [](int) { return 0.02; },
      [&](int s) {
        // near every strip border: x = k/n +- 0.03
        const int strip = s % n;
        return Vec2{L * (strip + 0.5) / n + (s % 2 ? -1.0 : 1.0) * (0.5 * L / n - 0.03),
                    0.1 + 0.06 * s};
      },
      [](int s) {
        return Vec2{0.1 * s, 0.0};
      });
  const dem::DemSolver& dem = *dem_ptr;
  const auto scene = dem::scene_of(&dem, {});
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

// scene_of_all (the replicated implicit viscous solve's scene): every solid of the run on every
// rank, gathered from the owners, ordered by id, each with its own state and placement; the
// obstacles as given. The solids are those of SceneOfTheDemIsOrderedById, on 1 or 2 ranks.
TEST(SolidSnapshot, SceneOfAllHoldsEverySolidOnEveryRank) {
  const core::Comm comm;
  const std::vector<std::int64_t> ids = {5, 2, 8, 0, 3};
  const auto radius = [](int s) { return 0.01 * (s + 1); };
  const auto at = [](int s) { return Vec2{0.1 + 0.2 * s, 0.25}; };  // spread over the strips
  const auto v = [](int s) { return Vec2{0.1 * s, -0.2 * s}; };
  const auto dem = strip_dem(comm, ids, radius, at, v);
  geometry::Obstacle o;
  o.name = "step";
  o.polygons = {{{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.05}, {0.0, 0.05}}};
  const auto all = dem::scene_of_all(dem.get(), {o});
  ASSERT_EQ(all.states.size(), 5u);
  ASSERT_EQ(all.placements.size(), 5u);
  ASSERT_EQ(all.obstacles.size(), 1u);
  EXPECT_EQ(all.obstacles[0].name, "step");
  // by id: 0 (s = 3), 2 (s = 1), 3 (s = 4), 5 (s = 0), 8 (s = 2)
  const int spec_of[] = {3, 1, 4, 0, 2};
  for (std::size_t b = 0; b < 5; ++b) {
    const int s = spec_of[b];
    EXPECT_EQ(all.states[b].id, ids[static_cast<std::size_t>(s)]);
    EXPECT_EQ(all.placements[b].id, ids[static_cast<std::size_t>(s)]);
    EXPECT_EQ(all.states[b].x.x, at(s).x);
    EXPECT_EQ(all.states[b].v.x, v(s).x);
    EXPECT_EQ(all.states[b].v.z, v(s).z);
    EXPECT_EQ(all.placements[b].pose.x.x, at(s).x);
    EXPECT_NEAR(all.placements[b].shape->bounding_radius(), radius(s), 1e-15);
  }
}

// place_solids takes the cut cells a step kept for the next (CutCellsAhead) only for the scene
// and the rank's window they were built for, and then gives the same cut cells and apertures as
// building them: moved out when a DEM moves the solids, kept for a scene of obstacles alone. Three
// disks and an obstacle on a 100 x 50 grid cut into one strip per rank.
TEST(CutCellsAhead, UsedOnlyForTheSceneAndWindowTheyWereBuiltFor) {
  const core::Comm comm;
  const auto dem = strip_dem(
      comm, {1, 2, 3}, [](int s) { return 0.031 + 0.01 * s; },
      [](int s) {
        return Vec2{0.2 + 0.3 * s, 0.2 + 0.01 * s};
      },
      [](int) { return Vec2{}; });
  geometry::Obstacle o;
  o.name = "step";
  o.polygons = {{{0.0, 0.0}, {0.13, 0.0}, {0.13, 0.052}, {0.0, 0.052}}};
  grid::GridSpec spec;
  spec.nx = 100, spec.nz = 50, spec.h = 0.01;
  grid::Decomposition d(spec, comm, 2);
  grid::Halo halo(d);
  const coupling::Layout L{d, halo, comm};
  coupling::StepSettings set;
  set.spec = spec, set.has_bodies = true, set.tiny_fraction = 1e-3;
  const auto same = [](const geometry::CutCells& a, const geometry::CutCells& b) {
    return a.ex == b.ex && a.ez == b.ez && a.fraction == b.fraction && a.body == b.body &&
           a.obstacle == b.obstacle && a.tiny == b.tiny && a.pieces.size() == b.pieces.size();
  };
  const dem::DemSolver* scenes[] = {dem.get(), nullptr};
  for (const dem::DemSolver* moving : scenes) {
    SCOPED_TRACE(moving ? "solids of a DEM" : "obstacles alone");
    coupling::CutCellsAhead ahead;
    fluid::Apertures E0, E;
    const auto fresh = coupling::place_solids(L, set, moving, {o}, E0, ahead);  // nothing kept
    EXPECT_EQ(ahead.valid, moving == nullptr);  // a still scene keeps what it built
    // kept cut cells marked so that their use shows; each key changed alone refuses them
    const auto keep = [&](auto change) {
      ahead = {true,
               fresh.scene.placements,
               fresh.scene.obstacles,
               d.storage(grid::Stagger::Cell),
               fresh.cut,
               E0};
      ahead.cut.pieces.push_back({});  // a piece no build makes (also where no body reaches)
      change(ahead);
    };
    keep([](coupling::CutCellsAhead&) {});
    auto used = coupling::place_solids(L, set, moving, {o}, E, ahead);
    EXPECT_EQ(used.cut.pieces.size(), fresh.cut.pieces.size() + 1);
    EXPECT_TRUE(E.E_x.data() == E0.E_x.data() && E.E_z.data() == E0.E_z.data());
    EXPECT_EQ(ahead.valid, moving == nullptr);
    const std::vector<void (*)(coupling::CutCellsAhead&)> changes = {
        [](coupling::CutCellsAhead& a) { a.valid = false; },
        [](coupling::CutCellsAhead& a) { a.window.i1 += 1; },
        [](coupling::CutCellsAhead& a) { a.obstacles[0].polygons[0][2].z += 1e-12; },
        [](coupling::CutCellsAhead& a) { a.obstacles.clear(); },
        [](coupling::CutCellsAhead& a) {
          if (!a.placements.empty())
            a.placements[0].pose.theta += 1e-12;
          else
            a.window.k0 -= 1;  // a rank without solids: another key
        },
        [](coupling::CutCellsAhead& a) {
          if (!a.placements.empty())
            a.placements[0].pose.x.x += 1e-12;
          else
            a.window.k1 += 1;
        },
        [](coupling::CutCellsAhead& a) { a.placements.push_back({}); },
    };
    for (std::size_t c = 0; c < changes.size(); ++c) {
      if (!moving && c >= 4) break;  // the obstacles alone have no placements
      keep(changes[c]);
      const auto built = coupling::place_solids(L, set, moving, {o}, E, ahead);
      EXPECT_TRUE(same(built.cut, fresh.cut)) << "change " << c;
      EXPECT_TRUE(E.E_x.data() == E0.E_x.data() && E.E_z.data() == E0.E_z.data()) << c;
    }
  }
}

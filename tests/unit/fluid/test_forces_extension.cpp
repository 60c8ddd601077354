// Gravity on faces next to fluid, apertures, divergence of a linear field, velocity extension
// into air, and the CFL time step, on 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "fluid_test_support.hpp"
#include "picdem/core/error.hpp"
#include "picdem/fluid/fluid.hpp"

using namespace picdem;
using namespace picdem::grid;

namespace {

using fluid_test::kAir;
using fluid_test::kFluid;

GridSpec make_spec(int nx, int nz, double h) {
  GridSpec s;
  s.nx = nx, s.nz = nz, s.h = h;
  return s;
}

/// Fluid in the lower `depth` rows, air above.
fluid::CellStates layer(const Decomposition& d, int depth) {
  fluid::CellStates c(d, Stagger::Cell, kAir);
  const auto& b = c.storage();
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i)
      if (i >= 0 && k >= 0 && i < d.spec().nx && k < depth) c(i, k) = kFluid;
  return c;
}

}  // namespace

TEST(FluidForces, GravityOnFacesNextToFluidOnly) {
  const GridSpec s = make_spec(10, 8, 0.05);
  core::Comm comm;
  Decomposition d(s, comm, 1);
  const auto cells = layer(d, 4);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  fluid::FluidConfig cfg;
  cfg.g = {0.5, -9.81};
  fluid::apply_gravity(u, w, cells, 0.01, cfg);
  const auto& bw = w.owned();
  for (int k = bw.k0; k < bw.k1; ++k)
    for (int i = bw.i0; i < bw.i1; ++i)
      // Faces k = 0..4 touch a fluid cell (k = 4 is the surface face); above: untouched.
      EXPECT_DOUBLE_EQ(w(i, k), k <= 4 ? -0.0981 : 0.0) << i << "," << k;
  const auto& bu = u.owned();
  for (int k = bu.k0; k < bu.k1; ++k)
    for (int i = bu.i0; i < bu.i1; ++i) EXPECT_DOUBLE_EQ(u(i, k), k < 4 ? 0.005 : 0.0);
}

TEST(FluidForces, AperturesClosedOnWallsAndDivergenceOfLinearField) {
  const GridSpec s = make_spec(9, 7, 0.1);
  core::Comm comm;
  Decomposition d(s, comm, 1);
  const auto E = fluid::open_apertures(d);
  for (int k = E.E_x.owned().k0; k < E.E_x.owned().k1; ++k)
    for (int i = E.E_x.owned().i0; i < E.E_x.owned().i1; ++i)
      EXPECT_EQ(E.E_x(i, k), (i == 0 || i == s.nx) ? 0.0 : 0.1);
  for (int k = E.E_z.owned().k0; k < E.E_z.owned().k1; ++k)
    for (int i = E.E_z.owned().i0; i < E.E_z.owned().i1; ++i)
      EXPECT_EQ(E.E_z(i, k), (k == 0 || k == s.nz) ? 0.0 : 0.1);
  // u = 2 x, w = -3 z: interior cells have D = E (2 h) + E (-3 h) = -h^2; wall cells lose the
  // closed faces' fluxes.
  const auto cells = layer(d, s.nz);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (int k = u.storage().k0; k < u.storage().k1; ++k)
    for (int i = u.storage().i0; i < u.storage().i1; ++i)
      u(i, k) = 2.0 * s.position(Stagger::FaceX, i, k).x;
  for (int k = w.storage().k0; k < w.storage().k1; ++k)
    for (int i = w.storage().i0; i < w.storage().i1; ++i)
      w(i, k) = -3.0 * s.position(Stagger::FaceZ, i, k).z;
  CellField D(d, Stagger::Cell, 0.0);
  fluid::divergence(u, w, E, cells, D);
  for (int k = D.owned().k0; k < D.owned().k1; ++k)
    for (int i = D.owned().i0; i < D.owned().i1; ++i) {
      const double h = s.h;
      double expect = 0.0;
      expect += (i + 1 < s.nx ? h * 2 * (i + 1) * h : 0.0) - (i > 0 ? h * 2 * i * h : 0.0);
      expect += (k + 1 < s.nz ? -3 * h * (k + 1) * h : 0.0) - (k > 0 ? -3 * h * k * h : 0.0);
      EXPECT_NEAR(D(i, k), expect, 1e-14) << i << "," << k;
    }
}

TEST(FluidExtension, FillsAirFacesLayerByLayer) {
  const GridSpec s = make_spec(12, 12, 0.1);
  core::Comm comm;
  Decomposition d(s, comm, 1);
  Halo halo(d);
  const auto cells = layer(d, 3);  // fluid rows 0..2; w faces 0..3 and u faces in rows 0..2
  const auto E = fluid::open_apertures(d);
  GridArray<signed char> uv(d, Stagger::FaceX, 0), wv(d, Stagger::FaceZ, 0);
  fluid::fluid_faces(cells, E, uv, wv);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  for (int k = u.storage().k0; k < u.storage().k1; ++k)
    for (int i = u.storage().i0; i < u.storage().i1; ++i)
      if (uv(i, k)) u(i, k) = 1.0 + i;
  for (int k = w.storage().k0; k < w.storage().k1; ++k)
    for (int i = w.storage().i0; i < w.storage().i1; ++i)
      if (wv(i, k)) w(i, k) = 2.0;
  const int layers = 3;
  fluid::extend_velocity(u, w, uv, wv, layers, halo);
  // w: valid faces k <= 3 (k = 0 is the wall, E = 0, so invalid but reached from k = 1).
  for (int k = w.owned().k0; k < w.owned().k1; ++k)
    for (int i = w.owned().i0; i < w.owned().i1; ++i) {
      const bool reached = (k >= 1 && k <= 3 + layers) || k == 0;
      EXPECT_EQ(w(i, k), reached ? 2.0 : 0.0) << i << "," << k;
    }
  // u: interior faces in rows 0..2 valid; rows 3..5 reached; columns keep their value (the
  // extension goes straight up first, so each column copies its own value).
  for (int k = u.owned().k0; k < u.owned().k1; ++k)
    for (int i = u.owned().i0; i < u.owned().i1; ++i) {
      if (i == 0 || i == s.nx) continue;  // wall faces: reset by enforce_walls afterwards
      EXPECT_EQ(u(i, k), k <= 2 + layers ? 1.0 + i : 0.0) << i << "," << k;
    }
}

namespace {

/// The extension as first written: owned faces only, a forward after every layer.
void extend_layer_by_layer(FaceField& f, GridArray<signed char> valid, int layers,
                           const Halo& halo) {
  halo.forward(valid);
  halo.forward(f);
  const auto& b = f.owned();
  for (int layer = 0; layer < layers; ++layer) {
    std::vector<std::pair<std::size_t, double>> updates;
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        if (valid(i, k)) continue;
        double sum = 0.0;
        int n = 0;
        const int di[4] = {1, -1, 0, 0}, dk[4] = {0, 0, 1, -1};
        for (int m = 0; m < 4; ++m)
          if (f.in_storage(i + di[m], k + dk[m]) && valid(i + di[m], k + dk[m]))
            sum += f(i + di[m], k + dk[m]), ++n;
        if (n > 0) updates.emplace_back(f.index(i, k), sum / n);
      }
    for (const auto& [idx, v] : updates) f.data()[idx] = v, valid.data()[idx] = 1;
    halo.forward(valid);
    halo.forward(f);
  }
}

/// A pseudo-random number in [0, 1) of the sample (i, k) and a salt, the same on every rank.
double noise(int i, int k, unsigned salt) {
  unsigned long long x = (static_cast<unsigned long long>(i + 100) * 1000003ULL) ^
                         (static_cast<unsigned long long>(k + 100) * 998244353ULL) ^ salt;
  x ^= x >> 33, x *= 0xff51afd7ed558ccdULL, x ^= x >> 33, x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return static_cast<double>(x >> 11) * 0x1.0p-53;
}

}  // namespace

// The band-limited extension with one forward per halo width gives the values of the
// layer-by-layer scheme bit for bit, owned and halo faces alike, for islands of valid faces,
// valid faces beyond the walls, halos of 1 to 3 and more layers than the halo is wide.
TEST(FluidExtension, MatchesLayerByLayerBitwise) {
  core::Comm comm;
  const GridSpec s = make_spec(23, 17, 0.1);
  for (int halo_width : {1, 2, 3})
    for (int layers : {1, 3, 5})
      for (double density : {0.03, 0.3}) {
        Decomposition d(s, comm, halo_width);
        Halo halo(d);
        for (Stagger st : {Stagger::FaceX, Stagger::FaceZ}) {
          FaceField f(d, st, 0.0);
          GridArray<signed char> valid(d, st, 0);
          const auto b = f.storage();
          for (int k = b.k0; k < b.k1; ++k)
            for (int i = b.i0; i < b.i1; ++i) {
              valid(i, k) = noise(i, k, 7) < density ? 1 : 0;
              f(i, k) = valid(i, k) ? noise(i, k, 11) - 0.5 : 0.0;
            }
          FaceField expect = f;
          extend_layer_by_layer(expect, valid, layers, halo);
          FaceField got = f, other(d, st == Stagger::FaceX ? Stagger::FaceZ : Stagger::FaceX);
          GridArray<signed char> other_valid(d, other.stagger(), 0);
          if (st == Stagger::FaceX)
            fluid::extend_velocity(got, other, valid, other_valid, layers, halo);
          else
            fluid::extend_velocity(other, got, other_valid, valid, layers, halo);
          for (int k = b.k0; k < b.k1; ++k)
            for (int i = b.i0; i < b.i1; ++i)
              ASSERT_EQ(got(i, k), expect(i, k))
                  << "halo " << halo_width << ", layers " << layers << ", density " << density
                  << ", stagger " << static_cast<int>(st) << ", face " << i << "," << k;
        }
      }
}

TEST(FluidTimeStep, CflOverAllRanks) {
  const GridSpec s = make_spec(10, 6, 0.02);
  core::Comm comm;
  Decomposition d(s, comm, 1);
  FaceField u(d, Stagger::FaceX, 0.0), w(d, Stagger::FaceZ, 0.0);
  if (w.owned().contains(9, 6)) w(9, 6) = -4.0;  // the top-right face, owned by the last rank
  EXPECT_DOUBLE_EQ(fluid::cfl_time_step(u, w, s.h, 0.5, 1.0, comm), 0.5 * 0.02 / 4.0);
  EXPECT_DOUBLE_EQ(fluid::cfl_time_step(u, w, s.h, 0.5, 1e-3, comm), 1e-3);
}

TEST(FluidParameters, DefaultsAndErrorsNameTheKey) {
  const auto p = fluid_test::tank_params(1.0, 0.5, 0.01);
  const auto cfg = fluid::config_from(p);
  EXPECT_EQ(cfg.rho, 1000.0);
  EXPECT_EQ(cfg.nu, 1e-6);
  EXPECT_EQ(cfg.g.x, 0.0);
  EXPECT_EQ(cfg.g.z, -9.81);
  EXPECT_FALSE(cfg.no_slip);
  EXPECT_EQ(cfg.h, 0.01);
  EXPECT_TRUE(
      fluid::config_from(fluid_test::tank_params(1.0, 0.5, 0.01, {"fluid/walls=no_slip"})).no_slip);
  for (const std::string bad : {"fluid/walls=sticky", "fluid/density=-1", "solver/tolerance=2"}) {
    try {
      fluid_test::tank_params(1.0, 0.5, 0.01, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const core::InputError& e) {
      const std::string key = bad.substr(0, bad.find('='));
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// 1, 2 and 3 ranks give the same velocities on the faces beside bodies: every rank builds the cut
// cells of its own window, sets the closed faces' rigid velocity (rigid_face_velocities) and the
// cut faces' mixture velocity (mix_cut_faces), and compares every face it stores with the same
// computation over the whole grid, bitwise. Bodies and a perforated pipe straddle the ranks'
// cut lines.
#include <gtest/gtest.h>

#include <cmath>

#include "cut_scene.hpp"
#include "picdem/core/comm.hpp"
#include "picdem/fluid/bodies.hpp"

using namespace picdem;
using core::Vec2;
using grid::Stagger;

namespace {

std::vector<core::SolidState> motions(const std::vector<geometry::SolidPlacement>& placed) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<core::SolidState> m;
  for (const auto& p : placed) {
    core::SolidState s;
    s.id = p.id, s.x = p.pose.x, s.v = {u(rng), u(rng)}, s.omega = 20.0 * u(rng);
    m.push_back(s);
  }
  return m;
}

// The velocities after both operations on the grid of `d`: smooth fields of the faces' global
// positions before, so that a rank's value can be compared with the whole grid's.
struct Faces {
  fluid::FluidState f;
  long long mixed = 0, closed = 0;
  Faces(const grid::Decomposition& d, const std::vector<geometry::SolidPlacement>& placed,
        const std::vector<geometry::Obstacle>& obstacles)
      : f(d) {
    const auto& spec = d.spec();
    const auto cut = fluid::cut_cells(placed, obstacles, 1e-3, d, f.apertures);
    for (auto [v, v_old, s] :
         {std::tuple{&f.u, &f.u_old, Stagger::FaceX}, std::tuple{&f.w, &f.w_old, Stagger::FaceZ}}) {
      const auto b = v->storage();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) {
          const Vec2 x = spec.position(s, i, k);
          (*v)(i, k) = std::sin(7.0 * x.x) + std::cos(5.0 * x.z);
          (*v_old)(i, k) = std::cos(3.0 * x.x * x.z);
        }
    }
    const auto m = motions(placed);
    fluid::rigid_face_velocities(m, cut, f.apertures, d, f.u, f.w, f.u_valid, f.w_valid);
    const fluid::FluidState before = f;
    fluid::mix_cut_faces(m, cut, d, f);
    for (auto [v, v0] : {std::pair{&f.u, &before.u}, std::pair{&f.w, &before.w}}) {
      const auto b = v->storage();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) mixed += (*v)(i, k) != (*v0)(i, k) ? 1 : 0;
    }
    for (auto* valid : {&f.u_valid, &f.w_valid}) {
      const auto b = valid->storage();
      for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i) closed += (*valid)(i, k) ? 1 : 0;
    }
  }
};

}  // namespace

TEST(BodyFacesRanks, StoredFacesEqualTheWholeGridComputation) {
  grid::GridSpec spec;
  spec.nx = 64;
  spec.nz = 48;
  spec.h = 1.0 / 64;
  core::Comm comm;
  const auto obstacles = test_support::perforated_pipe();
  const auto placed = test_support::random_solids(5, 0.04, 7);
  const int halo = 3;  // the production width (coupling: max(3, what the schemes need))
  const grid::Decomposition mine(spec, comm, halo);
  const grid::Decomposition whole(spec, core::Comm(MPI_COMM_SELF), halo);
  const Faces a(mine, placed, obstacles), b(whole, placed, obstacles);

  // Faces of the grid's interior and its walls that this rank stores (owned and halo).
  long long compared = 0;
  auto same = [&](const auto& va, const auto& vb, Stagger s, const char* what) {
    const auto box = va.storage().intersect(spec.extent(s));
    for (int k = box.k0; k < box.k1; ++k)
      for (int i = box.i0; i < box.i1; ++i, ++compared)
        if (va(i, k) != vb(i, k)) {
          ADD_FAILURE() << what << " (" << i << ", " << k << ") on rank " << comm.rank() << ": "
                        << double(va(i, k)) << " against " << double(vb(i, k));
          return;
        }
  };
  same(a.f.u, b.f.u, Stagger::FaceX, "u");
  same(a.f.w, b.f.w, Stagger::FaceZ, "w");
  same(a.f.u_old, b.f.u_old, Stagger::FaceX, "u_old");
  same(a.f.w_old, b.f.w_old, Stagger::FaceZ, "w_old");
  same(a.f.u_valid, b.f.u_valid, Stagger::FaceX, "u_valid");
  same(a.f.w_valid, b.f.w_valid, Stagger::FaceZ, "w_valid");
  EXPECT_GT(compared, 0);
  // The scene exercises both operations on every rank's window.
  EXPECT_GT(a.mixed, 50);
  EXPECT_GT(a.closed, 50);
}

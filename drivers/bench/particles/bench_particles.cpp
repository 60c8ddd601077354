// Particles per second through P2G (to_grid), G2P (from_grid, FLIP and APIC), advection (RK2,
// RK3) and migration, on n x n grids with 4 particles per cell filling the tank.
//   mpirun -n <ranks> bench_particles [n ...]      (default: 128 256 512 1024)
// Prints one row per grid: global particles and million particles per second per phase
// (wall clock of the slowest rank).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "picdem/particles/particles.hpp"

using namespace picdem;
using namespace picdem::particles;

namespace {

/// Seconds per call of f, the slowest rank's, averaged over `reps` calls.
template <class F>
double time_per_call(const core::Comm& comm, int reps, F&& f) {
  comm.barrier();
  const double t0 = MPI_Wtime();
  for (int r = 0; r < reps; ++r) f();
  return comm.max(MPI_Wtime() - t0) / reps;
}

void run(const core::Comm& comm, int n) {
  grid::GridSpec s;
  s.nx = n, s.nz = n, s.h = 1.0 / n;
  ParticleConfig c;
  grid::Decomposition d(s, comm, required_halo(c));
  grid::Halo halo(d);
  ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
  // a rigid rotation about the tank centre, with |v| dt <= h/2 everywhere
  grid::FaceField u(d, grid::Stagger::FaceX), w(d, grid::Stagger::FaceZ);
  for (auto* g : {&u, &w}) {
    const core::IndexBox b = g->storage();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) {
        const core::Vec2 v =
            core::cross(1.0, s.position(g->stagger(), i, k) - core::Vec2{0.5, 0.5});
        (*g)(i, k) = g == &u ? v.x : v.z;
      }
  }
  for (std::size_t m = 0; m < p.size(); ++m) {
    const core::Vec2 v = core::cross(1.0, core::Vec2{p.x[m] - 0.5, p.z[m] - 0.5});
    p.u[m] = v.x, p.w[m] = v.z;
  }
  const double dt = 0.5 * s.h / 0.71;
  const double total = comm.sum(static_cast<double>(p.size()));
  const int reps = std::max(2, static_cast<int>(1.6e7 / total));
  grid::FaceField gu, gw, mu, mw;
  ParticleConfig apic = c;
  apic.transfer = TransferScheme::Apic;
  ParticleConfig rk3 = c;
  rk3.advection = AdvectionScheme::Rk3;

  const double t_p2g = time_per_call(comm, reps, [&] { to_grid(p, d, halo, c, gu, gw, mu, mw); });
  const double t_p2g_apic =
      time_per_call(comm, reps, [&] { to_grid(p, d, halo, apic, gu, gw, mu, mw); });
  const double t_g2p = time_per_call(comm, reps, [&] { from_grid(p, c, u, w, u, w, s); });
  const double t_g2p_apic = time_per_call(comm, reps, [&] { from_grid(p, apic, u, w, u, w, s); });
  double t_adv = 0.0, t_adv3 = 0.0, t_mig = 0.0;
  for (int r = 0; r < reps; ++r) {
    t_adv += time_per_call(comm, 1, [&] { advect(p, c, u, w, s, dt); });
    t_mig += time_per_call(comm, 1, [&] { migrate(p, d); });
    t_adv3 += time_per_call(comm, 1, [&] { advect(p, rk3, u, w, s, dt); });
    migrate(p, d);
  }
  t_adv /= reps, t_adv3 /= reps, t_mig /= reps;
  const double after = comm.sum(static_cast<double>(p.size()));
  if (comm.is_root()) {
    const auto rate = [&](double t) { return total / t / 1e6; };
    std::printf(
        "%5d^2 %2d ranks %9.0f particles | Mparticles/s: P2G flip %6.1f apic %6.1f | "
        "G2P flip %6.1f apic %6.1f | advect rk2 %6.1f rk3 %6.1f | migrate %6.1f%s\n",
        n, comm.size(), total, rate(t_p2g), rate(t_p2g_apic), rate(t_g2p), rate(t_g2p_apic),
        rate(t_adv), rate(t_adv3), rate(t_mig), after == total ? "" : "  (PARTICLES LOST)");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    core::Comm comm;
    std::vector<int> sizes;
    for (int a = 1; a < argc; ++a) sizes.push_back(std::atoi(argv[a]));
    if (sizes.empty()) sizes = {128, 256, 512, 1024};
    for (int n : sizes) run(comm, n);
  }
  MPI_Finalize();
  return 0;
}

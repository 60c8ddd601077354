// Particles per second through P2G (to_grid), G2P (from_grid, FLIP and APIC), advection (RK2,
// RK3) and migration, on n x n grids with 4 particles per cell filling the tank.
//   mpirun -n <ranks> bench_particles [n ...]      (default: 128 256 512 1024)
// Prints one row per grid: global particles and million particles per second per phase
// (wall clock of the slowest rank).
//   mpirun -n <ranks> bench_particles --fuse-ab [--rounds R] [n ...]
// A/B of marking + P2G: (A) occupancy with the count, then to_grid, two passes over the particles,
// against (B) occupancy with the count and P2G's sums in one pass, then to_grid(sums), alternated
// R times (default 9); prints the medians of wall and of CPU time (this process's, which a loaded
// machine inflates far less), A/B, whether B gives A's fields bit for bit, and the load average
// (/proc/loadavg) before and after.
#include <mpi.h>

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "picdem/particles/occupancy.hpp"
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

/// The tank of n x n cells filled with seeded particles, in a rigid rotation about its centre.
ParticleSet rotating_tank(const grid::Decomposition& d, const ParticleConfig& c) {
  ParticleSet p = seed(d, c, [](core::Vec2) { return true; });
  for (std::size_t m = 0; m < p.size(); ++m) {
    const core::Vec2 v = core::cross(1.0, core::Vec2{p.x[m] - 0.5, p.z[m] - 0.5});
    p.u[m] = v.x, p.w[m] = v.z;
  }
  return p;
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

template <class T>
bool same_bits(const grid::GridArray<T>& a, const grid::GridArray<T>& b) {
  return a.data().size() == b.data().size() &&
         std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(T)) == 0;
}

/// This process's CPU seconds.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void fuse_ab(const core::Comm& comm, int n, int rounds) {
  grid::GridSpec s;
  s.nx = n, s.nz = n, s.h = 1.0 / n;
  ParticleConfig c;
  grid::Decomposition d(s, comm, required_halo(c));
  grid::Halo halo(d);
  const ParticleSet p = rotating_tank(d, c);
  const double total = comm.sum(static_cast<double>(p.size()));
  const int reps = std::max(2, static_cast<int>(4e6 / total));
  const std::string load_before = comm.is_root() ? load_average() : "";
  grid::CellField Sa(d, grid::Stagger::Cell), Sb(d, grid::Stagger::Cell);
  grid::GridArray<int> ca(d, grid::Stagger::Cell), cb(d, grid::Stagger::Cell);
  grid::FaceField ua, wa, mua, mwa, ub, wb, mub, mwb;
  GridSums sums;
  std::vector<double> ta, tb, ca_cpu, cb_cpu;  // wall and CPU seconds per call
  for (int r = 0; r < rounds; ++r) {
    double c0 = cpu_seconds();
    ta.push_back(time_per_call(comm, reps, [&] {
      occupancy(p, d, halo, 4, Sa, &ca);
      to_grid(p, d, halo, c, ua, wa, mua, mwa);
    }));
    double c1 = cpu_seconds();
    ca_cpu.push_back(comm.max(c1 - c0) / reps);
    tb.push_back(time_per_call(comm, reps, [&] {
      occupancy(p, d, halo, 4, Sb, cb, c, sums);
      to_grid(sums, halo, ub, wb, mub, mwb);
    }));
    cb_cpu.push_back(comm.max(cpu_seconds() - c1) / reps);
  }
  const bool same = !comm.any(!(same_bits(Sa, Sb) && same_bits(ca, cb) && same_bits(ua, ub) &&
                                same_bits(wa, wb) && same_bits(mua, mub) && same_bits(mwa, mwb)));
  if (comm.is_root()) {
    const double a = median(ta), b = median(tb), ac = median(ca_cpu), bc = median(cb_cpu);
    std::printf(
        "%5d^2 %2d ranks %9.0f particles | mark + P2G, medians of %d alternated rounds x %d "
        "calls, wall (CPU) ns per particle: A two passes %.1f (%.1f), B one pass %.1f (%.1f), "
        "A/B %.3f (%.3f) | bitwise %s | load %s -> %s\n",
        n, comm.size(), total, rounds, reps, 1e9 * a / total, 1e9 * ac / total, 1e9 * b / total,
        1e9 * bc / total, a / b, ac / bc, same ? "yes" : "NO", load_before.c_str(),
        load_average().c_str());
    std::fflush(stdout);
  }
}

void run(const core::Comm& comm, int n) {
  grid::GridSpec s;
  s.nx = n, s.nz = n, s.h = 1.0 / n;
  ParticleConfig c;
  grid::Decomposition d(s, comm, required_halo(c));
  grid::Halo halo(d);
  ParticleSet p = rotating_tank(d, c);
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
    bool ab = false;
    int rounds = 9;
    for (int a = 1; a < argc; ++a) {
      if (std::strcmp(argv[a], "--fuse-ab") == 0)
        ab = true;
      else if (std::strcmp(argv[a], "--rounds") == 0 && a + 1 < argc)
        rounds = std::max(1, std::atoi(argv[++a]));
      else
        sizes.push_back(std::atoi(argv[a]));
    }
    if (sizes.empty()) sizes = {128, 256, 512, 1024};
    for (int n : sizes) ab ? fuse_ab(comm, n, rounds) : run(comm, n);
  }
  MPI_Finalize();
  return 0;
}

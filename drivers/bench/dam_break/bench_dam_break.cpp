// Benchmark: the dam break at N x N cells (N = 128, 256, 512, 1024 by default), on however many
// ranks it is started with. Prints time per step split by phase, pressure solver iterations and
// setup/solve split, particles per second through the transfers, the cost of every phase per
// fluid cell and per particle per step, and peak memory per rank. On a shared machine the
// process's CPU time over the timed steps gives the share of a core each rank got; the cost
// columns are also given scaled by it (what a rank holding a whole core would take).
//   mpirun -n 2 build/drivers/bench/dam_break/bench_dam_break [steps] [N ...]
// With `coupled`: the 6-layer cylinder dam break (cases/dam_break_cylinders_6_layers) at cell
// size h (0.5 mm, 20 cells per diameter, by default), and the same water without the cylinders,
// timed from t0 (0.1 s: the collapse under way) for `steps` steps; adds wall seconds per
// simulated second. `coupled_cylinders`: the cylinders only, timed from t0 (0.1 s by default; at
// least 5 warm-up steps are taken, so 0 times steps 6 to 5 + steps).
//   mpirun -n 2 build/drivers/bench/dam_break/bench_dam_break coupled [steps] [h ...]
//   mpirun -n 2 build/drivers/bench/dam_break/bench_dam_break coupled_cylinders [steps] [t0] [h
//   ...]
#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include "picdem/core/log.hpp"
#include "picdem/core/params.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/fluid/pressure_solver.hpp"

namespace {
double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

// User + system CPU seconds of this process.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Fluid cells over all ranks' owned cells.
double fluid_cells(const picdem::core::Comm& comm, const picdem::coupling::Simulation& sim) {
  const auto& c = sim.fluid().cells;
  const auto b = c.owned();
  const auto fluid = static_cast<signed char>(picdem::grid::CellState::Fluid);
  long long n = 0;
  for (int k = b.k0; k < b.k1; ++k)
    for (int i = b.i0; i < b.i1; ++i) n += c(i, k) == fluid;
  return static_cast<double>(comm.sum(n));
}

// The step's phases are the top-level timers; "fluid: ...", "particles: ...", "dem: ...",
// "io: ..." are inside them.
bool nested(const std::string& name) {
  for (const char* p : {"fluid:", "particles:", "dem:", "io:", "checkpoint:"})
    if (name.rfind(p, 0) == 0) return true;
  return false;
}

// Cost per unit of work: wall time of each phase per step over the fluid cells (all ranks) and
// over the particles (all ranks), means over the timed steps; and the same times `share`.
void print_costs(const std::map<std::string, double>& t, int steps, double cells, double particles,
                 double share) {
  double total = 0.0;
  for (const auto& kv : t)
    if (!nested(kv.first)) total += kv.second;
  std::printf("  %-46s %9s  %6s %14s %14s %12s %12s\n", "phase (rank 0's timers)", "ms/step",
              "share", "us/fluid cell", "ns/particle", "us/cell x c", "ns/ptcl x c");
  for (const auto& kv : t) {
    const double per_step = kv.second / steps;
    const double per_cell = cells > 0 ? 1e6 * per_step / cells : 0.0;
    const double per_particle = particles > 0 ? 1e9 * per_step / particles : 0.0;
    std::printf("  %s%-44s %9.2f  %5.1f%% %14.3f %14.1f %12.3f %12.1f\n",
                nested(kv.first) ? "  " : "", kv.first.c_str(), 1e3 * per_step,
                100 * kv.second / total, per_cell, per_particle, per_cell * share,
                per_particle * share);
  }
}

// Runs to t0, then times `steps` steps and prints the figures under `label`.
void measure(const picdem::core::Comm& comm, const std::string& label,
             const picdem::core::Params& params, int steps, double t0) {
  picdem::coupling::Simulation sim(comm, params);
  for (int s = 0; s < 5 || sim.time() < t0; ++s) sim.step();
  picdem::core::reset_timers();
  long long its = 0, reused = 0;
  double simulated = 0.0, cells = 0.0, particles_sum = 0.0;
  const double cpu0 = cpu_seconds(), wall0 = picdem::core::wall_seconds();
  for (int s = 0; s < steps; ++s) {
    sim.step();
    its += sim.diagnostics().ppe_iterations;
    reused += sim.diagnostics().ppe_structure_reused ? 1 : 0;
    simulated += sim.diagnostics().dt;
    cells += fluid_cells(comm, sim);
    particles_sum += static_cast<double>(sim.diagnostics().particles);
  }
  // The share of a core this rank got over the timed steps (1 on an idle machine).
  const double core_share = (cpu_seconds() - cpu0) / (picdem::core::wall_seconds() - wall0);
  const double share_min = comm.min(core_share), share_max = comm.max(core_share);
  cells /= steps, particles_sum /= steps;
  const auto t = picdem::core::timer_totals();
  double total = 0.0;
  for (const auto& kv : t)
    if (!nested(kv.first)) total += kv.second;
  const double particles = static_cast<double>(sim.diagnostics().particles);
  const double mem = comm.max(peak_rss_mb());
  if (comm.is_root()) {
    std::printf(
        "\n%s, %.0f particles, from t = %.3f s: %.2f ms/step, %.1f PPE iterations/step, mean dt "
        "%.3e s, %.1f wall s per simulated s, peak %.0f MB/rank\n",
        label.c_str(), particles, sim.time() - simulated, 1e3 * total / steps, double(its) / steps,
        simulated / steps, total / simulated, mem);
    std::printf("  %.0f fluid cells, %.0f particles (means over the timed steps)\n", cells,
                particles_sum);
    // CPU / wall of the timed steps: the share of a core a rank got (busy-waiting in MPI counts).
    std::printf(
        "  share of a core per rank over the timed steps: %.2f to %.2f (rank 0 %.2f); the "
        "two right columns are the cost columns times rank 0's share\n",
        share_min, share_max, core_share);
    print_costs(t, steps, cells, particles_sum, core_share);
    auto get = [&](const char* k) { return t.count(k) ? t.at(k) : 0.0; };
    // The pressure system's Tpetra structure (maps, graph, Export) is rebuilt when the fluid mask
    // or the coupled cells change, else only its values are refilled.
    const long long rebuilt = steps - reused;
    std::printf(
        "  pressure structure reused in %lld of %d steps; %.2f ms per rebuild, values "
        "%.2f ms per step\n",
        reused, steps, rebuilt > 0 ? 1e3 * get("fluid: pressure structure") / rebuilt : 0.0,
        1e3 * get("fluid: pressure values") / steps);
    const double transfer = get("transfer: particles to grid") + get("transfer: grid to particles");
    if (transfer > 0)
      std::printf("  transfers: %.2e particles/s (P2G + G2P)\n", particles * steps / transfer);
  }
}

int coupled(const picdem::core::Comm& comm, int argc, char** argv, bool with_water) {
  const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
  // coupled_cylinders: the third argument is t0 (0.1 s unless given)
  const int first_size = with_water ? 3 : 4;
  const double t0 = !with_water && argc > 3 ? std::atof(argv[3]) : 0.1;
  std::vector<double> sizes;
  for (int n = first_size; n < argc; ++n) sizes.push_back(std::atof(argv[n]));
  if (sizes.empty()) sizes = {0.0005};
  const auto schema = picdem::coupling::case_schema();
  const std::string src = PICDEM_SOURCE_DIR;
  for (double h : sizes) {
    const std::vector<std::string> common = {"grid/cell_size=" + std::to_string(h), "time/end=100",
                                             "output/progress_seconds=1e9"};
    auto with = common;
    const auto cylinders = picdem::core::read_case(
        comm, src + "/cases/dam_break_cylinders_6_layers/case.yaml", with, schema);
    auto without = common;
    for (const char* o : {"grid/length=0.286", "grid/height=0.2", "water/column/x=[0.0, 0.066]",
                          "water/column/z=[0.0, 0.12]", "time/dt_max=0.0005"})
      without.push_back(o);
    const auto water =
        picdem::core::read_case(comm, src + "/cases/dam_break/case.yaml", without, schema);
    char label[128];
    std::snprintf(label, sizeof label, "6 layers of cylinders, h = %.2f mm", 1e3 * h);
    measure(comm, label, cylinders, steps, t0);
    if (!with_water) continue;
    std::snprintf(label, sizeof label, "the same water without cylinders, h = %.2f mm", 1e3 * h);
    measure(comm, label, water, steps, 0.1);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  picdem::fluid::LinearAlgebraScope scope(&argc, &argv);
  picdem::core::Comm comm;
  if (argc > 1 && std::string(argv[1]) == "coupled") return coupled(comm, argc, argv, true);
  if (argc > 1 && std::string(argv[1]) == "coupled_cylinders")
    return coupled(comm, argc, argv, false);
  const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
  std::vector<int> sizes;
  for (int n = 2; n < argc; ++n) sizes.push_back(std::atoi(argv[n]));
  if (sizes.empty()) sizes = {128, 256, 512, 1024};
  const auto schema = picdem::coupling::case_schema();
  if (comm.is_root())
    std::printf("dam break benchmark, %d rank(s), %d timed steps after 5 warm-up steps\n",
                comm.size(), steps);
  for (int n : sizes) {
    // A square tank of side 4a, the column a x 2a, n x n cells.
    const double a = 0.05715, L = 4 * a;
    std::vector<std::string> o = {
        "grid/length=" + std::to_string(L), "grid/height=" + std::to_string(L),
        "grid/cell_size=" + std::to_string(L / n), "time/end=100", "output/progress_seconds=1e9"};
    const auto params = picdem::core::read_case(
        comm, std::string(PICDEM_SOURCE_DIR) + "/cases/dam_break/case.yaml", o, schema);
    measure(comm, std::to_string(n) + "^2 cells", params, steps, 0.0);
  }
  return 0;
}

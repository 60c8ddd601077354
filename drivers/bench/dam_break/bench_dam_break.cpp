// Benchmark: the dam break at N x N cells (N = 128, 256, 512, 1024 by default), on however many
// ranks it is started with. Prints time per step split by phase, pressure solver iterations and
// setup/solve split, particles per second through the transfers, and peak memory per rank.
//   mpirun -n 2 build/drivers/bench/dam_break/bench_dam_break [steps] [N ...]
#include <cstdio>
#include <fstream>
#include <string>

#include "picdem/core/params.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/fluid/pressure_solver.hpp"

namespace {
double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}
}  // namespace

int main(int argc, char** argv) {
  picdem::fluid::LinearAlgebraScope scope(&argc, &argv);
  picdem::core::Comm comm;
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
    picdem::coupling::Simulation sim(comm, params, "");
    for (int s = 0; s < 5; ++s) sim.step();
    picdem::core::reset_timers();
    long long its = 0;
    for (int s = 0; s < steps; ++s) {
      sim.step();
      its += sim.diagnostics().ppe_iterations;
    }
    const auto t = picdem::core::timer_totals();
    // The step's phases are the top-level timers; "fluid: ...", "particles: ...", "dem: ...",
    // "io: ..." are inside them.
    auto nested = [](const std::string& name) {
      for (const char* p : {"fluid:", "particles:", "dem:", "io:", "checkpoint:"})
        if (name.rfind(p, 0) == 0) return true;
      return false;
    };
    double total = 0.0;
    for (const auto& kv : t)
      if (!nested(kv.first)) total += kv.second;
    const double particles = static_cast<double>(sim.diagnostics().particles);
    const double mem = comm.max(peak_rss_mb());
    if (comm.is_root()) {
      std::printf(
          "\n%d^2 cells, %.0f particles: %.2f ms/step, %.1f PPE iterations/step, peak %.0f "
          "MB/rank\n",
          n, particles, 1e3 * total / steps, double(its) / steps, mem);
      for (const auto& kv : t)
        std::printf("  %s%-32s %9.2f ms/step  %5.1f%%\n", nested(kv.first) ? "  " : "",
                    kv.first.c_str(), 1e3 * kv.second / steps, 100 * kv.second / total);
      auto get = [&](const char* k) { return t.count(k) ? t.at(k) : 0.0; };
      const double transfer =
          get("transfer: particles to grid") + get("transfer: grid to particles");
      if (transfer > 0)
        std::printf("  transfers: %.2e particles/s (P2G + G2P)\n", particles * steps / transfer);
    }
  }
  return 0;
}

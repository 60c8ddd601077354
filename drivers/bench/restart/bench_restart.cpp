// Whole-state checkpoint figures: write time, read (restart) time and file size, per million
// particles, for the four disks in water of tests/restart/run/disks_in_water.yaml, refined (its
// solids stay clear of rank boundaries).
//   mpirun -n R build/drivers/bench/restart/bench_restart [CELL_SIZE] [REPEATS] [DIR]
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "picdem/core/comm.hpp"
#include "picdem/core/log.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/run/run.hpp"

int main(int argc, char** argv) {
  picdem::fluid::LinearAlgebraScope scope(&argc, &argv);
  picdem::core::Comm comm;
  const std::string h = argc > 1 ? argv[1] : "0.00015";
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::string dir = argc > 3 ? argv[3] : ".";
  const auto params = picdem::core::read_case(
      comm, std::string(PICDEM_SOURCE_DIR) + "/tests/restart/run/disks_in_water.yaml",
      {"grid/cell_size=" + h}, picdem::coupling::case_schema());
  picdem::coupling::Simulation sim(comm, params);
  sim.step();  // a state with velocities, pressure and cell states
  const double particles = static_cast<double>(sim.diagnostics().particles);
  const std::string path = dir + "/bench_restart.h5";

  double write = 1e300, read = 1e300;
  for (int r = 0; r < repeats; ++r) {
    comm.barrier();
    double t0 = picdem::core::wall_seconds();
    picdem::run::Run(sim).write_checkpoint(path);
    write = std::min(write, comm.max(picdem::core::wall_seconds() - t0));
    picdem::coupling::Simulation restored(comm, params);
    picdem::run::Run restored_run(restored);
    comm.barrier();
    t0 = picdem::core::wall_seconds();
    restored_run.restart_from(path, "");
    read = std::min(read, comm.max(picdem::core::wall_seconds() - t0));
  }
  struct stat st {};
  stat(path.c_str(), &st);
  const double mb = static_cast<double>(st.st_size) / 1e6, per = 1e6 / particles;
  char line[400];
  std::snprintf(line, sizeof line,
                "ranks %d  cell %s m  particles %.0f  file %.1f MB (%.1f MB per 1e6 particles)  "
                "write %.3f s (%.3f s per 1e6)  read %.3f s (%.3f s per 1e6)  best of %d",
                comm.size(), h.c_str(), particles, mb, mb * per, write, write * per, read,
                read * per, repeats);
  picdem::core::log(comm, line);
  if (comm.is_root()) std::remove(path.c_str());
  return 0;
}

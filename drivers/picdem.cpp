// picdem: run a case.  picdem CASE.yaml [--set KEY=VALUE ...] [--output DIR] [--max-steps N]
//                                       [--restart PATH|latest]
//         picdem --check CASE.yaml [--set ...]     validate only
//         picdem --help-parameters                  the case-file reference (Markdown)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "input_checks.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/schema.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/pressure_solver.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/run/run.hpp"
#include "run_record.hpp"

namespace {

const char* usage =
    "usage: picdem CASE.yaml [--set KEY=VALUE ...] [--output DIR] [--max-steps N]\n"
    "                        [--restart PATH|latest]\n"
    "       picdem --check CASE.yaml [--set KEY=VALUE ...]\n"
    "       picdem --help-parameters\n"
    "CASE.yaml may also be a directory holding case.yaml (cases/dam_break).\n"
    "Run under mpirun for more ranks. KEY is a case-file path such as grid/cell_size.\n"
    "--restart continues from a checkpoint file, or from the newest one in the checkpoint\n"
    "directory (latest); SIGTERM or SIGUSR1 makes the run write a checkpoint and exit 0.\n";

struct Args {
  std::string case_file, output, restart;
  std::vector<std::string> overrides;
  long long max_steps = 0;
  bool check = false, help_parameters = false, help = false;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int n = 1; n < argc; ++n) {
    const std::string s = argv[n];
    auto value = [&](const char* what) {
      if (n + 1 >= argc) throw picdem::core::InputError(s + " needs " + what);
      return std::string(argv[++n]);
    };
    if (s == "--set") {
      a.overrides.push_back(value("KEY=VALUE"));
    } else if (s.rfind("--set=", 0) == 0) {
      a.overrides.push_back(s.substr(6));
    } else if (s == "--output" || s == "-o") {
      a.output = value("a directory");
    } else if (s == "--max-steps") {
      const std::string v = value("a number of steps");
      char* end = nullptr;
      a.max_steps = std::strtoll(v.c_str(), &end, 10);
      if (*end || a.max_steps <= 0)
        throw picdem::core::InputError("--max-steps " + v + ": expected a positive integer");
    } else if (s == "--restart") {
      a.restart = value("a checkpoint file or 'latest'");
    } else if (s == "--check") {
      a.check = true;
    } else if (s == "--help-parameters") {
      a.help_parameters = true;
    } else if (s == "--help" || s == "-h") {
      a.help = true;
    } else if (!s.empty() && s[0] == '-') {
      throw picdem::core::InputError("unknown option " + s + "\n" + usage);
    } else if (a.case_file.empty()) {
      a.case_file = s;
    } else {
      throw picdem::core::InputError("more than one case file given (" + a.case_file + ", " + s +
                                     ")");
    }
  }
  return a;
}

// What a run leaves besides its results: the log (rank 0's output) and run.yaml.
struct RunParts {
  RunParts(const picdem::core::Comm& comm, int argc, char** argv) : record(comm, argc, argv) {}
  picdem::driver::LogTee log;
  picdem::driver::RunRecord record;
  std::unique_ptr<picdem::coupling::Simulation> sim;
  std::unique_ptr<picdem::run::Run> steps;  // the time loop, output and checkpoints of sim
  void finish(const std::string& status, int code, const std::string& message) {
    if (sim) {
      const auto split = sim->grid_split();
      record.split(split.x_cuts, split.z_cuts);
    }
    record.finish(status, code, sim ? sim->step_count() : 0, sim ? sim->time() : 0.0, message);
  }
};

// The solids' resolution, which every run states (issue 14): their number, the range of their
// bounding diameters, the contact law's dt_DEM and eq. 25's subcycles at time/dt_max
// (K = INT(dt / dt_DEM), each dt / K long). Collective; nothing without solids.
void log_solids(const picdem::core::Comm& comm, const picdem::coupling::Simulation& sim,
                const picdem::core::Params& params) {
  const picdem::dem::DemSolver* dem = sim.dem();
  if (!dem) return;
  const auto all = dem->gather_all();
  if (all.empty()) return;
  double d_min = 1e300, d_max = 0.0;
  for (const auto& s : all) {
    const double d = 2.0 * dem->shape_of(s.id)->bounding_radius();
    d_min = std::min(d_min, d), d_max = std::max(d_max, d);
  }
  const double dt_max = params.real("time/dt_max"), dt_dem = dem->dt_dem();
  const double k = std::max(1.0, std::floor(dt_max / dt_dem));  // a double: no overflow
  char text[320];
  std::snprintf(text, sizeof text,
                "picdem: %zu solids, bounding diameters %.4g to %.4g m; dt_DEM = %.4g s, at "
                "time/dt_max = %.4g s %.0f subcycles of %.4g s",
                all.size(), d_min, d_max, dt_dem, dt_max, k, dt_max / k);
  picdem::core::log(comm, text);
}

// The viscosity the transfer's PIC share adds (doc/particles.md, "The PIC share as a viscosity"):
// each step hands a particle (1 - r) of the grid's interpolated velocity, a smoothing by the tent
// of variance h^2 / 6, i.e. about (1 - r) h^2 / (6 dt); stated at time/dt_max, its smallest value,
// beside fluid/viscosity, so that a run whose result is the viscous stress sees when it is not
// small. Nothing for pure FLIP, APIC or a dry run.
void log_transfer_viscosity(const picdem::core::Comm& comm, const picdem::coupling::Simulation& sim,
                            const picdem::core::Params& params) {
  if (!sim.has_fluid() || params.string("transfer/scheme") != "flip") return;
  const double r = params.real("transfer/flip_ratio");
  if (r >= 1.0) return;
  const double h = params.real("grid/cell_size"), dt = params.real("time/dt_max");
  const double nu_pic = (1.0 - r) * h * h / (6.0 * dt), nu = params.real("fluid/viscosity");
  char text[400];
  std::snprintf(text, sizeof text,
                "picdem: transfer/flip_ratio = %.4g: the PIC share smooths like a viscosity of "
                "about %.3g m^2/s at time/dt_max (more at shorter steps), against fluid/viscosity "
                "= %.3g m^2/s",
                r, nu_pic, nu);
  std::string line = text;
  if (nu > 0.0) line += " (" + std::to_string(std::lround(100.0 * nu_pic / nu)) + "% of it)";
  picdem::core::log(comm, line + "; doc/particles.md");
}

// The explicit viscous scheme gives the bodies no viscous load (doc/viscous.md, "In the step"):
// with a fluid more viscous than water and solids or obstacles in it, a run whose forces.csv
// shows zero viscous columns says so. A disk spinning at 20 rad/s in nu = 1e-2 m^2/s kept 99.8% of
// its spin over 0.3 s; the implicit scheme took it to 0.33 rad/s in 0.1 s.
void log_viscous_loads(const picdem::core::Comm& comm, const picdem::coupling::Simulation& sim,
                       const picdem::core::Params& params) {
  constexpr double water = 1e-6;  // m^2/s, the default: the paper's setting
  const double nu = params.real("fluid/viscosity");
  if (!sim.has_fluid() || params.string("fluid/viscosity_scheme") != "explicit" || nu <= water)
    return;
  if (params.sublist_names("solids").empty() && params.sublist_names("obstacles").empty()) return;
  char text[480];
  std::snprintf(text, sizeof text,
                "picdem: fluid/viscosity = %.3g m^2/s (water: 1e-6) with fluid/viscosity_scheme = "
                "explicit: solids and obstacles feel the pressure only, no viscous force or "
                "torque (forces.csv's viscous columns stay 0); fluid/viscosity_scheme: implicit "
                "adds them with no-slip at their true boundary (doc/viscous.md)",
                nu);
  picdem::core::log(comm, text);
}

// The tank is a whole number of cells (grid::spec_from rounds grid/length and grid/height): a
// length that is not says the tank's true size, as the shipped cases run at other cell sizes do
// (0.286 m at 1.5 mm is 190.67 cells: the tank is 0.2865 m long).
void log_grid_rounding(const picdem::core::Comm& comm, const picdem::core::Params& params) {
  const double h = params.real("grid/cell_size");
  for (const char* key : {"grid/length", "grid/height"}) {
    const double asked = params.real(key), cells = asked / h;
    const double n = std::round(cells);
    if (std::abs(n * h - asked) <= 1e-9 * asked) continue;
    char text[360];
    std::snprintf(text, sizeof text,
                  "picdem: %s = %.6g m is %.6g cells of grid/cell_size = %.6g m: the tank is %.0f "
                  "cells, %.6g m (water, solids and obstacles keep their coordinates)",
                  key, asked, cells, h, n, n * h);
    picdem::core::log(comm, text);
  }
}

// Runs the case (after the parameters are read); the log and run.yaml from the moment the output
// folder is known.
int run_case(const picdem::core::Comm& comm, const Args& args, const picdem::core::Params& params,
             RunParts& run) {
  std::string out = args.output.empty() ? params.string("output/directory") : args.output;
  if (out.empty()) out = "output/" + params.string("case/name");
  run.log.open(comm, out + "/picdem.log", !args.restart.empty());
  picdem::core::log(comm, "picdem: case " + args.case_file + " on " + std::to_string(comm.size()) +
                              " rank(s), output in " + out);
  const auto checkpoints = picdem::io::checkpoint_config_from(params, out);
  const std::string from = args.restart == "latest"
                               ? picdem::io::latest_checkpoint(comm, checkpoints.directory)
                               : args.restart;
  run.record.start(out, args.case_file, params, from);
  {
    picdem::core::ScopedTimer timer("setup");  // grid, seeding, solids, solvers (timers.txt)
    run.sim = std::make_unique<picdem::coupling::Simulation>(comm, params);
  }
  log_grid_rounding(comm, params);
  log_solids(comm, *run.sim, params);
  log_transfer_viscosity(comm, *run.sim, params);
  log_viscous_loads(comm, *run.sim, params);
  run.steps = std::make_unique<picdem::run::Run>(*run.sim);
  if (from.empty())
    run.steps->open_output(out);
  else
    run.steps->restart_from(from, out);
  run.record.first_step(run.sim->step_count());
  const auto split = run.sim->grid_split();
  run.record.split(split.x_cuts, split.z_cuts);
  picdem::io::install_stop_signal_handlers();
  run.steps->enable_checkpoints(checkpoints.directory);
  run.steps->run(args.max_steps);
  run.finish(run.steps->stopped_by_signal() ? "stopped_by_signal" : "completed", 0, "");
  return 0;
}

/// The process's virtual and peak resident sizes from /proc/self/status ("unknown memory"
/// elsewhere).
std::string process_size_text() {
  std::ifstream in("/proc/self/status");
  std::string line, text;
  while (std::getline(in, line))
    if (line.rfind("VmSize:", 0) == 0 || line.rfind("VmHWM:", 0) == 0) {
      std::istringstream in_line(line);
      std::string key, value, unit;
      in_line >> key >> value >> unit;
      text += (text.empty() ? "" : ", ") + key + " " + value + " " + unit;
    }
  return text.empty() ? "unknown memory" : text;
}

}  // namespace

int main(int argc, char** argv) {
  // Kokkos answers --help with its own options: it sees the arguments without it.
  std::vector<char*> kept;
  for (int n = 0; n < argc; ++n)
    if (std::string(argv[n]) != "--help" && std::string(argv[n]) != "-h") kept.push_back(argv[n]);
  int kept_argc = static_cast<int>(kept.size());
  kept.push_back(nullptr);
  char** kept_argv = kept.data();
  picdem::fluid::LinearAlgebraScope scope(&kept_argc, &kept_argv);  // MPI + Kokkos for Tpetra
  picdem::core::Comm comm;
  RunParts run(comm, argc, argv);
  double memory_estimate = 0.0;
  try {
    Args args = parse(argc, argv);
    if (args.help) {
      picdem::core::log(comm, usage);
      return 0;
    }
    const auto schema = picdem::run::case_schema();
    if (args.help_parameters) {
      picdem::core::log(comm,
                        "# Case-file reference\n\nGenerated by `picdem --help-parameters` "
                        "from the parameter declarations in the code.\n\n" +
                            picdem::driver::checks_markdown() + schema.reference_markdown());
      return 0;
    }
    if (args.case_file.empty())
      throw picdem::core::InputError(std::string("no case file\n") + usage);
    args.case_file = picdem::core::case_file_path(comm, args.case_file);  // DIR: DIR/case.yaml
    const auto params = picdem::core::read_case(comm, args.case_file, args.overrides, schema);
    picdem::driver::check_case(comm, params);  // placement, solver lists, memory (doc/cases.md)
    memory_estimate = picdem::driver::memory_estimate_bytes(params, comm.size());
    if (args.check) {
      picdem::core::log(comm, args.case_file + ": valid");
      return 0;
    }
    return run_case(comm, args, params, run);
  } catch (const picdem::core::InputError& e) {
    // Raised identically on every rank (input is validated everywhere): report once, exit cleanly.
    picdem::core::log_error(comm, std::string("picdem: error: ") + e.what());
    run.finish("input_error", 2, e.what());
    return 2;
  } catch (const picdem::core::SolverError& e) {
    picdem::core::log_error(comm, std::string("picdem: the run stopped: ") + e.what());
    run.finish("solver_error", 3, e.what());
    return 3;
  } catch (const std::bad_alloc& e) {
    // One rank ran out: the others cannot know, so this stays an abort, with what to change.
    std::cerr << "picdem: rank " << comm.rank() << ": out of memory (std::bad_alloc), process size "
              << process_size_text()
              << " (VmHWM: the peak resident size); the estimate before the run was "
              << memory_estimate / 1e9
              << " GB per rank: make grid/cell_size larger, particles/per_cell_1d smaller, run on "
                 "more ranks or set run/memory_limit_gb to what a rank may really use"
              << std::endl;
    run.finish("crashed", 4, "out of memory (std::bad_alloc)");
    MPI_Abort(comm.raw(), 4);
    return 4;
  } catch (const std::exception& e) {
    std::cerr << "picdem: rank " << comm.rank() << ": unexpected error: " << e.what() << std::endl;
    run.finish("crashed", 4, e.what());  // written when rank 0 is the one that caught it
    MPI_Abort(comm.raw(), 4);
    return 4;
  }
}

#pragma once
// The coupled PIC-DEM run: owns the state of every module and advances it one step at a time in
// the order of the paper's Fig. 4. Nothing here includes Trilinos or CGAL.
#include <memory>
#include <string>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"

namespace picdem::coupling {

struct SimulationState;

/// Figures of the state, recorded every step in timeseries.csv.
struct Diagnostics {
  double t = 0.0;
  double dt = 0.0;
  long long step = 0;
  double fluid_volume = 0.0;    ///< area inside the particles' free surface [m^2] (free_surface.hpp)
  double kinetic_energy = 0.0;  ///< fluid, from the particles, per unit depth [J/m]
  int ppe_iterations = 0;
  double ppe_residual = 0.0;
  double front_x = 0.0;         ///< largest x of any fluid particle, from the left wall [m]
  long long particles = 0;
  double max_speed = 0.0;
  double solid_kinetic_energy = 0.0;
};

class Simulation {
 public:
  /// `output_dir` empty: no files are written (tests).
  Simulation(core::Comm comm, core::Params params, std::string output_dir);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Runs to time/end (or `max_steps` steps if > 0), writing output on the way.
  void run(long long max_steps = 0);
  /// One coupled step.
  void step();

  const Diagnostics& diagnostics() const;
  double time() const;
  long long step_count() const;
  const core::Params& params() const;

  /// Pressure at a point, sampled from the cell holding it (the owning rank's value on all ranks).
  double pressure_at(double x, double z) const;
  /// Largest fluid speed on the grid faces next to fluid cells.
  double max_grid_speed() const;

 private:
  std::unique_ptr<SimulationState> s_;
};

}  // namespace picdem::coupling

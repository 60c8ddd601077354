#include "picdem/coupling/schema.hpp"

#include <sstream>

#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/particles/particles.hpp"

namespace picdem::coupling {

void declare_parameters(core::ParamSchema& s) {
  s.section("case", "What the case is.");
  s.string("case/name", "unnamed", {}, "short name, used in output file headers");

  s.section("time", "Simulated time and the adaptive time step.");
  s.real("time/end", 1.0,
         "simulated time to reach [s]; the run ends with the first step at or past it (the last "
         "step is not shortened, so continuing to a later end follows the same trajectory)")
      .positive()
      .is_required();
  s.real("time/cfl", 0.5, "CFL number: dt <= cfl h / max|u| on the grid").positive().at_most(5.0);
  s.string("time/cfl_speed", "particles", {"particles", "grid"},
           "the speed of the CFL bound: the largest of the grid's face velocities and the "
           "particles' speeds (particles), or of the grid's face velocities, which move the "
           "particles, and the solids' surface speeds (grid; doc/coupling.md)");
  s.real("time/dt_max", 1e-3, "largest time step [s]").positive();
  s.real("time/dt_min", 1e-8, "smallest time step [s]; a step below it stops the run as blown up")
      .positive();

  s.section("output", "What the run writes, and how often.");
  s.string("output/directory", "", {},
           "output folder (empty: output/<case/name>); the command line's --output wins");
  s.real("output/interval", 0.05, "simulated time between frames (ParaView, PNG, solids.csv) [s]")
      .positive();
  s.boolean("output/paraview", true, "write XDMF + HDF5 frames");
  s.boolean("output/png", true, "write a PNG picture with every frame");
  s.integer("output/png_width", 1000, "width of the PNG pictures [pixels]")
      .at_least(200)
      .at_most(8000);
  s.real("output/png_speed_max", 0.0,
         "speed at the top of the pictures' colour bar, the same in every frame [m/s]; 0: "
         "sqrt(2 g H), H the initial water's height above the floor (the tank's without water)")
      .at_least(0.0);
  s.boolean("output/movie", false,
            "at the end, join the pictures into pictures/movie.mp4 (ffmpeg; without it "
            "movie.gif through python3-pil)");
  s.real("output/movie_fps", 10.0, "frames per second of the movie").positive().at_most(120.0);
  s.reals("output/level_probes", {},
          "x positions [m] whose free-surface height is recorded in timeseries.csv (level_1, ...)")
      .size(0, 32);
  s.reals("output/solid_count_box", {},
          "[x_min, x_max, z_min, z_max] [m]: solids whose centre is inside are counted in "
          "timeseries.csv (solids_in_box); empty: no count")
      .size(0, 4);
  s.real("output/forces_interval", 0.0,
         "simulated time between the rows of forces.csv (the fluid's loads on every solid and "
         "obstacle) [s]; 0: every step")
      .non_negative();
  s.real("output/progress_seconds", 5.0, "wall seconds between progress lines").non_negative();

  s.section("free_surface", "The free surface from the particles (doc/coupling.md).");
  s.string("free_surface/method", "ghost_fluid", {"ghost_fluid", "cells"},
           "p = 0 on the particles' level set S = 1/2 between cell centres (ghost fluid), or at "
           "the centres of cells without particles");
  s.real("free_surface/theta_min", 0.01,
         "smallest distance fraction of a fluid-air face to the surface (ghost fluid)")
      .greater_than(0.0)
      .at_most(1.0);
  s.real("free_surface/density_correction", 0.0,
         "share of the particles' excess or missing density (S - 1) moved away each step, "
         "positions only (doc/coupling.md); 0: off")
      .at_least(0.0)
      .at_most(1.0);
  s.integer("free_surface/density_correction_interval", 1,
            "steps between density corrections (each costs a second Poisson solve)")
      .at_least(1);

  s.section("coupling", "The fluid-solid coupling.");
  s.real("coupling/beta", 0.5,
         "gap damping (eq. 20): particle velocity factor at a contact point; 1 switches it off")
      .at_least(0.0)
      .at_most(1.0);
  s.boolean("coupling/hydrostatic_quadrature", true,
            "carry the cell pressure to each wetted piece along rho g in the solid loads "
            "(false: the cell-centre value, as the paper)");
  s.boolean("coupling/viscous_rigid_rows", false,
            "fluid/viscosity_scheme implicit: the solids' rigid velocities are unknowns of the "
            "viscous step (stable for light solids; 2 more solves per component and solid); "
            "false: the split, the fluid's wall value the solid's start-of-step velocity, unstable "
            "for solids much lighter than the fluid (doc/viscous.md)");
  s.real("coupling/tiny_cell_fraction", 1e-3,
         "cut cells with a smaller fluid fraction are made solid (doc/geometry.md)")
      .at_least(0.0)
      .less_than(0.5);

  auto& water = s.family("water", "Where the fluid is at t = 0 (their union; none: a dry run).");
  auto& box = water.variant("box", "an axis-aligned block of water");
  box.reals("x", {0.0, 0.1}, "[x_min, x_max] of the block [m]").size(2, 2);
  box.reals("z", {0.0, 0.1}, "[z_min, z_max] of the block [m]").size(2, 2);
  auto& level = water.variant("level", "all of the tank below a still-water level");
  level.real("z", 0.1, "still-water level [m]");

  s.check([](const core::Params& p, std::vector<std::string>& errors) {
    const auto count_box = p.reals("output/solid_count_box");
    if (!count_box.empty() &&
        (count_box.size() != 4 || !(count_box[0] < count_box[1]) || !(count_box[2] < count_box[3])))
      errors.push_back(
          "key 'output/solid_count_box' must be empty or [x_min, x_max, z_min, z_max] "
          "with min < max");
    // Solids and water must feel the same gravity.
    if (!p.sublist_names("water").empty() && !p.sublist_names("solids").empty() &&
        p.reals("dem/gravity") != p.reals("fluid/gravity"))
      errors.push_back(
          "keys 'dem/gravity' and 'fluid/gravity' differ; with water and solids in "
          "one case they must be the same");
    const auto o = p.reals("grid/origin");
    const double x0 = o[0], z0 = o[1];
    const double x1 = x0 + p.real("grid/length"), z1 = z0 + p.real("grid/height");
    for (const auto& name : p.sublist_names("water")) {
      const auto w = p.sub("water/" + name);
      std::ostringstream msg;
      msg.precision(10);
      if (w.string("type") == "box") {
        const auto x = w.reals("x"), z = w.reals("z");
        if (!(x[0] < x[1]) || !(z[0] < z[1])) {
          msg << "water/" << name << ": x = [" << x[0] << ", " << x[1] << "], z = [" << z[0] << ", "
              << z[1] << "] is empty; give [min, max] with min < max";
          errors.push_back(msg.str());
        } else if (x[0] < x0 || x[1] > x1 || z[0] < z0 || z[1] > z1) {
          msg << "water/" << name << ": the block x = [" << x[0] << ", " << x[1] << "], z = ["
              << z[0] << ", " << z[1] << "] reaches outside the tank x in [" << x0 << ", " << x1
              << "], z in [" << z0 << ", " << z1 << "]";
          errors.push_back(msg.str());
        }
      } else {
        const double z = w.real("z");
        if (z <= z0 || z > z1) {
          msg << "key 'water/" << name << "/z' = " << z
              << " is not allowed: the level must lie in (" << z0 << ", " << z1
              << "], inside the tank";
          errors.push_back(msg.str());
        }
      }
    }
  });
}

core::ParamSchema case_schema() {
  core::ParamSchema s;
  declare_parameters(s);
  grid::declare_parameters(s);
  fluid::declare_parameters(s);
  particles::declare_parameters(s);
  geometry::declare_obstacle_parameters(s);
  dem::declare_parameters(s);
  io::declare_checkpoint_parameters(s);
  return s;
}

}  // namespace picdem::coupling

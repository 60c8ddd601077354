// The output/ keys (output_parameters.hpp).
#include "picdem/io/output_parameters.hpp"
#include <sstream>

namespace picdem::io {

void declare_output_parameters(core::ParamSchema& s) {
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
  s.check([](const core::Params& p, std::vector<std::string>& errors) {
    const auto count_box = p.reals("output/solid_count_box");
    if (!count_box.empty() &&
        (count_box.size() != 4 || !(count_box[0] < count_box[1]) || !(count_box[2] < count_box[3])))
      errors.push_back(
          "key 'output/solid_count_box' must be empty or [x_min, x_max, z_min, z_max] "
          "with min < max");
    // a probe outside the tank would record NaN (no fluid) all run long
    const double x0 = p.reals("grid/origin").at(0), x1 = x0 + p.real("grid/length");
    // a count box that misses the tank would count 0 solids all run long
    const double z0 = p.reals("grid/origin").at(1), z1 = z0 + p.real("grid/height");
    if (count_box.size() == 4 && count_box[0] < count_box[1] && count_box[2] < count_box[3] &&
        !(count_box[1] > x0 && count_box[0] < x1 && count_box[3] > z0 && count_box[2] < z1)) {
      std::ostringstream m;
      m << "key 'output/solid_count_box' = [" << count_box[0] << ", " << count_box[1] << ", "
        << count_box[2] << ", " << count_box[3]
        << "] is not allowed: the box lies outside the tank x in [" << x0 << ", " << x1
        << "], z in [" << z0 << ", " << z1
        << "] (grid/origin, grid/length, grid/height) and would count no solid";
      errors.push_back(m.str());
    }
    for (const double x : p.reals("output/level_probes"))
      if (!(x >= x0 && x <= x1)) {
        std::ostringstream m;
        m << "key 'output/level_probes' = " << x
          << " is not allowed: a probe must lie in the tank, "
          << "x in [" << x0 << ", " << x1 << "] (grid/origin, grid/length)";
        errors.push_back(m.str());
      }
  });
}

}  // namespace picdem::io

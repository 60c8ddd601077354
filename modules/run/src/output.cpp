#include "picdem/run/output.hpp"

#include "diagnostic_columns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/io/csv_writer.hpp"
#include "picdem/io/frame_writer.hpp"
#include "picdem/io/render.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::run {

namespace fs = std::filesystem;

namespace {

// Title, time, step and the colour range of the pictures: output/png_speed_max, or else
// sqrt(2 g H) with H the initial water's height above the tank floor (the tank height in a dry
// run), the same in every frame of a run so that colours compare between frames.
io::SnapshotStyle snapshot_style(const core::Params& params, const grid::GridSpec& spec, double t,
                                 long long step) {
  double water_top = -std::numeric_limits<double>::infinity();
  for (const auto& name : params.sublist_names("water")) {
    const auto w = params.sub("water/" + name);
    water_top = std::max(water_top, w.string("type") == "box" ? w.reals("z")[1] : w.real("z"));
  }
  const double depth = std::isfinite(water_top) ? water_top - spec.origin.z : spec.height();
  io::SnapshotStyle s;
  s.width_pixels = static_cast<int>(params.integer("output/png_width"));
  const auto g = params.reals("fluid/gravity");
  const double g_abs = g.size() == 2 ? std::hypot(g[0], g[1]) : 9.81;
  s.speed_max = params.real("output/png_speed_max") > 0.0
                    ? params.real("output/png_speed_max")
                    : std::sqrt(2.0 * (g_abs > 0.0 ? g_abs : 9.81) * std::max(depth, spec.h));
  // Discs 1.6 seeding spacings across, so that still water reads as one surface.
  s.particle_radius = 0.8 * spec.h / static_cast<double>(params.integer("particles/per_cell_1d"));
  s.title = params.string("case/name");
  s.time = t;
  s.step = step;
  return s;
}

// The first multiple of `interval` after t (t itself counts as reached within 1e-9 intervals), the
// next frame or forces row due: a function of t alone, so a restart continues the same series.
double next_multiple(double t, double interval) {
  return interval * std::floor(t / interval + 1e-9) + interval;
}

}  // namespace

Output::Output(core::Comm comm, const core::Params& params, const grid::Decomposition& d,
               std::string directory, const Mark* resume, double resume_t)
    : comm_(comm),
      params_(params),
      decomp_(d),
      dir_(std::move(directory)),
      interval_(params.real("output/interval")) {
  const bool append = resume != nullptr;
  if (resume) {
    // output/interval may change on restart: the next frame is the checkpoint's or the first
    // multiple of the new interval after the restart time, whichever comes first. With the
    // interval unchanged the two agree (the checkpoint's was computed the same way from the last
    // frame's time, which is at most resume_t), so an unchanged case restarts bitwise.
    next_frame_ = std::min(resume->next_frame, next_multiple(resume_t, interval_));
    frames_ = resume->frames, last_frame_step_ = resume->last_frame_step;
  }
  if (comm_.is_root()) {
    fs::create_directories(dir_);
    if (params_.boolean("output/png")) fs::create_directories(dir_ + "/pictures");
    std::ofstream(dir_ + "/case_resolved.yaml") << params_.to_yaml();
  }
  comm_.barrier();
  if (params_.boolean("output/paraview"))
    frames_writer_ = std::make_unique<io::FrameWriter>(
        dir_, d, append, resume ? resume->last_frame_step : std::numeric_limits<long long>::max(),
        io::code_version());
  std::vector<std::string> columns = diagnostic_names();
  const auto probes = params.reals("output/level_probes");
  for (std::size_t n = 0; n < probes.size(); ++n)
    columns.push_back("level_" + std::to_string(n + 1));
  if (!params.reals("output/solid_count_box").empty()) columns.push_back("solids_in_box");
  if (fluid::config_from(params).open.any())  // doc/open_boundaries.md
    columns.insert(columns.end(), {"inflow_volume", "outflow_volume"});
  timeseries_ =
      std::make_unique<io::CsvWriter>(comm_, dir_ + "/timeseries.csv", columns, append, resume_t);
  solids_ = std::make_unique<io::CsvWriter>(
      comm_, dir_ + "/solids.csv",
      std::vector<std::string>{"t", "id", "x", "z", "theta", "u", "w", "omega"}, append, resume_t);
  forces_ = std::make_unique<io::CsvWriter>(
      comm_, dir_ + "/forces.csv",
      std::vector<std::string>{"t", "id", "obstacle", "pressure_x", "pressure_z", "viscous_x",
                               "viscous_z", "torque_pressure", "torque_viscous"},
      append, resume_t);
  forces_interval_ = params.real("output/forces_interval");
  // the next time due, a function of t alone (a restart continues the same series)
  if (forces_interval_ > 0.0 && resume) next_forces_ = next_multiple(resume_t, forces_interval_);
}

Output::~Output() = default;

void Output::record(const coupling::Diagnostics& g) {
  std::vector<double> row = diagnostic_scalars(g);
  row.insert(row.end(), g.levels.begin(), g.levels.end());
  if (!params_.reals("output/solid_count_box").empty())
    row.push_back(static_cast<double>(g.solids_in_box));
  row.insert(row.end(), g.open_volumes.begin(), g.open_volumes.end());
  timeseries_->row(row);
}

bool Output::forces_due(double t) const {
  return t >= next_forces_ - 1e-12 * std::max(1.0, forces_interval_);
}

void Output::forces(double t, const std::vector<BodyForces>& rows) {
  for (const auto& r : rows)
    forces_->row({t, static_cast<double>(r.id), r.obstacle ? 1.0 : 0.0, r.pressure.x, r.pressure.z,
                  r.viscous.x, r.viscous.z, r.torque_pressure, r.torque_viscous});
  if (forces_interval_ > 0.0) next_forces_ = next_multiple(t, forces_interval_);
}

void Output::frame(const coupling::Simulation& sim, bool force) {
  const double t = sim.time();
  if (!force && t < next_frame_ - 1e-12 * std::max(1.0, interval_)) return;
  write_frame(sim);
  ++frames_;
  next_frame_ = next_multiple(t, interval_);
}

void Output::write_frame(const coupling::Simulation& sim) {
  core::ScopedTimer timer("output");
  const double t = sim.time();
  const long long step = sim.step_count();
  const particles::ParticleSet& ps = sim.particles();
  const dem::DemSolver* dem = sim.dem();
  const std::vector<geometry::Obstacle>& obstacles = sim.obstacles();
  const auto& spec = decomp_.spec();
  io::PointSet points;
  points.x = ps.x;
  points.z = ps.z;
  auto& speed = points.scalars["speed"];
  speed.resize(ps.x.size());
  for (std::size_t n = 0; n < ps.x.size(); ++n) speed[n] = std::hypot(ps.u[n], ps.w[n]);
  points.vectors["velocity"] = {ps.u, ps.w};
  points.integers["id"].assign(ps.id.begin(), ps.id.end());
  points.units = {{"speed", "m/s"}, {"velocity", "m/s"}, {"id", "1"}};

  io::Polylines solid_lines, obstacle_lines;
  if (dem) {
    // Outlines: each rank its owned solids; solids.csv: every solid, by id, from rank 0.
    for (const auto& st : dem->owned()) {
      const auto shape = dem->shape_of(st.id);
      solid_lines.lines.push_back(geometry::outline(*shape, {st.x, st.theta}, 0.5 * spec.h));
      solid_lines.body_id.push_back(st.id);
    }
    for (const auto& st : dem->gather_all())
      solids_->row(
          {t, static_cast<double>(st.id), st.x.x, st.x.z, st.theta, st.v.x, st.v.z, st.omega});
  }
  // Fixed obstacles are known everywhere: rank 0 passes them.
  for (std::size_t o = 0; comm_.is_root() && o < obstacles.size(); ++o)
    for (const auto& line : geometry::outlines(obstacles[o])) {
      obstacle_lines.lines.push_back(line);
      obstacle_lines.body_id.push_back(static_cast<std::int64_t>(o));
    }

  last_frame_step_ = step;
  if (frames_writer_) {
    const fluid::CellStates air(decomp_, grid::Stagger::Cell, 0);
    io::CellArrays arrays;
    if (sim.has_fluid()) {  // the fluid's pressure and cell states; without water, air
      arrays.reals["pressure"] = &sim.fluid().p;
      arrays.codes["cell_state"] = &sim.fluid().cells;
    } else {
      arrays.codes["cell_state"] = &air;
    }
    arrays.units = {{"pressure", "Pa"}, {"cell_state", "code"}};
    frames_writer_->write(t, step, arrays, points, solid_lines, obstacle_lines);
  }
  if (params_.boolean("output/png")) {
    const core::Box2 tank{spec.origin, spec.origin + core::Vec2{spec.length(), spec.height()}};
    char name[64];  // the step, as the HDF5 frame
    std::snprintf(name, sizeof name, "/pictures/frame_%06lld.png", step);
    io::render_snapshot(comm_, dir_ + name, tank, points, solid_lines, obstacle_lines,
                        snapshot_style(params_, spec, t, step));
  }
}

void Output::finish(const coupling::Simulation& sim) {
  // The last state as a frame unless the last frame already holds this step.
  const long long step = sim.step_count();
  if (step != last_frame_step_) write_frame(sim);
  std::string movie;
  if (params_.boolean("output/png") && params_.boolean("output/movie") && comm_.is_root()) {
    const auto m = io::make_movie(dir_ + "/pictures", step, params_.real("output/movie_fps"));
    movie = "\n  " + (m.path.empty() ? m.message : "movie: " + m.path + " (" + m.message + ")");
  }
  std::ostringstream table;
  core::summarize_timers(comm_, table);
  if (comm_.is_root()) std::ofstream(dir_ + "/timers.txt") << table.str();
  // Only what this run wrote: a case with output/png or output/paraview false has no pictures
  // or ParaView files, and the list must not send the user looking for them.
  std::string written;
  if (params_.boolean("output/png"))
    written += "\n  pictures/frame_NNNNNN.png (NNNNNN = step)" + movie;
  if (params_.boolean("output/paraview"))
    written +=
        "\n  picdem.xdmf + frames/*.h5 (ParaView; one grid each: cells.xdmf, "
        "particles.xdmf, solids.xdmf, obstacles.xdmf)";
  core::log(comm_,
            "output in " + fs::absolute(dir_).string() + ":" + written +
                "\n  timeseries.csv, solids.csv, forces.csv, case_resolved.yaml, timers.txt");
}

}  // namespace picdem::run

#include "picdem/coupling/output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "picdem/core/log.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/coupling/checkpoint.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/outline.hpp"
#include "picdem/io/csv_writer.hpp"
#include "picdem/io/frame_writer.hpp"

namespace picdem::coupling {

namespace fs = std::filesystem;

Output::Output(core::Comm comm, const core::Params& params, const grid::Decomposition& d,
               std::string directory, const Mark* resume, double resume_t)
    : comm_(comm),
      params_(params),
      decomp_(d),
      dir_(std::move(directory)),
      interval_(params.real("output/interval")) {
  const bool append = resume != nullptr;
  if (resume)
    next_frame_ = resume->next_frame, frames_ = resume->frames,
    last_frame_step_ = resume->last_frame_step;
  if (comm_.is_root()) {
    fs::create_directories(dir_);
    fs::create_directories(dir_ + "/pictures");
    std::ofstream(dir_ + "/case_resolved.yaml") << params_.to_yaml();
  }
  comm_.barrier();
  if (params_.boolean("output/paraview"))
    frames_writer_ = std::make_unique<io::FrameWriter>(
        dir_, d, append, resume ? resume->last_frame_step : std::numeric_limits<long long>::max(),
        code_version());
  std::vector<std::string> columns = Diagnostics::scalar_names();
  const auto probes = params.reals("output/level_probes");
  for (std::size_t n = 0; n < probes.size(); ++n)
    columns.push_back("level_" + std::to_string(n + 1));
  if (!params.reals("output/solid_count_box").empty()) columns.push_back("solids_in_box");
  timeseries_ =
      std::make_unique<io::CsvWriter>(comm_, dir_ + "/timeseries.csv", columns, append, resume_t);
  solids_ = std::make_unique<io::CsvWriter>(
      comm_, dir_ + "/solids.csv",
      std::vector<std::string>{"t", "id", "x", "z", "theta", "u", "w", "omega"}, append, resume_t);
}

Output::~Output() = default;

void Output::record(const Diagnostics& g) {
  std::vector<double> row = g.scalars();
  row.insert(row.end(), g.levels.begin(), g.levels.end());
  if (!params_.reals("output/solid_count_box").empty())
    row.push_back(static_cast<double>(g.solids_in_box));
  timeseries_->row(row);
}

void Output::frame(double t, long long step, const Diagnostics&, const particles::ParticleSet& ps,
                   const grid::CellField& p, const fluid::CellStates& cells,
                   const dem::DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles,
                   bool force) {
  if (!force && t < next_frame_ - 1e-12 * std::max(1.0, interval_)) return;
  char name[64];
  std::snprintf(name, sizeof name, "frame_%06lld.png", frames_);
  write_frame(t, step, ps, p, cells, dem, obstacles, name, true);
  ++frames_;
  next_frame_ = interval_ * std::floor(t / interval_ + 1e-9) + interval_;
}

void Output::write_frame(double t, long long step, const particles::ParticleSet& ps,
                         const grid::CellField& p, const fluid::CellStates& cells,
                         const dem::DemSolver* dem,
                         const std::vector<geometry::Obstacle>& obstacles,
                         const std::string& png_name, bool data) {
  core::ScopedTimer timer("output");
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
      if (data)
        solids_->row(
            {t, static_cast<double>(st.id), st.x.x, st.x.z, st.theta, st.v.x, st.v.z, st.omega});
  }
  // Fixed obstacles are known everywhere: rank 0 passes them.
  for (std::size_t o = 0; comm_.is_root() && o < obstacles.size(); ++o)
    for (const auto& line : geometry::outlines(obstacles[o])) {
      obstacle_lines.lines.push_back(line);
      obstacle_lines.body_id.push_back(static_cast<std::int64_t>(o));
    }

  if (data) last_frame_step_ = step;
  if (frames_writer_ && data) {
    const fluid::CellStates air(decomp_, grid::Stagger::Cell, 0);
    io::CellArrays arrays;
    if (!p.data().empty()) arrays.reals["pressure"] = &p;
    arrays.codes["cell_state"] = cells.data().empty() ? &air : &cells;
    arrays.units = {{"pressure", "Pa"}, {"cell_state", "code"}};
    frames_writer_->write(t, step, arrays, points, solid_lines, obstacle_lines);
  }
  if (params_.boolean("output/png")) {
    const core::Box2 tank{spec.origin, spec.origin + core::Vec2{spec.length(), spec.height()}};
    io::render_snapshot(comm_, dir_ + "/pictures/" + png_name, tank, points, solid_lines,
                        obstacle_lines, static_cast<int>(params_.integer("output/png_width")));
  }
}

void Output::finish(double t, long long step, const Diagnostics&, const particles::ParticleSet& ps,
                    const grid::CellField& p, const fluid::CellStates& cells,
                    const dem::DemSolver* dem, const std::vector<geometry::Obstacle>& obstacles) {
  // The last state as final.png; its frame data unless the last frame already holds this step.
  write_frame(t, step, ps, p, cells, dem, obstacles, "final.png", step != last_frame_step_);
  std::ostringstream table;
  core::summarize_timers(comm_, table);
  if (comm_.is_root()) std::ofstream(dir_ + "/timers.txt") << table.str();
  core::log(comm_, "output in " + fs::absolute(dir_).string() +
                       ":\n  pictures/final.png (last state), pictures/frame_*.png\n  picdem.xdmf "
                       "+ frames/*.h5 (open picdem.xdmf in ParaView)\n  timeseries.csv, "
                       "solids.csv, case_resolved.yaml, timers.txt");
}

}  // namespace picdem::coupling

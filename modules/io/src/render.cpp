// The standard picture of a state (render_snapshot), drawn by rank 0 from gathered data.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/io/frame_writer.hpp"
#include "picdem/io/image.hpp"

namespace picdem::io {
namespace {

// Every rank's doubles concatenated in rank order, on rank 0 (empty elsewhere).
std::vector<double> gather_to_root(const core::Comm& comm, const std::vector<double>& mine) {
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(comm.size())), displs(counts.size());
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm.raw());
  std::vector<double> all;
  if (comm.is_root()) {
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      displs[r] = total;
      total += counts[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0,
              comm.raw());
  return all;
}

// Packed as: per line its vertex count, then x z pairs.
std::vector<double> pack(const Polylines& p) {
  std::vector<double> out;
  for (const auto& l : p.lines) {
    out.push_back(static_cast<double>(l.size()));
    for (const auto& v : l) out.insert(out.end(), {v.x, v.z});
  }
  return out;
}

std::vector<std::vector<core::Vec2>> unpack(const std::vector<double>& d) {
  std::vector<std::vector<core::Vec2>> lines;
  for (std::size_t m = 0; m < d.size();) {
    const auto n = static_cast<std::size_t>(d[m++]);
    lines.emplace_back();
    for (std::size_t v = 0; v < n; ++v, m += 2) lines.back().push_back({d[m], d[m + 1]});
  }
  return lines;
}

}  // namespace

void render_snapshot(const core::Comm& comm, const std::string& png_path, const core::Box2& tank,
                     const PointSet& particles, const Polylines& solids, const Polylines& obstacles,
                     int width_pixels) {
  core::ScopedTimer timer("io: picture");
  const double length = tank.hi.x - tank.lo.x, height = tank.hi.z - tank.lo.z;
  if (!(length > 0.0 && height > 0.0))
    throw core::InputError("render_snapshot: the tank box must have positive length and height");
  if (width_pixels < 64 || width_pixels > 16384)
    throw core::InputError("render_snapshot: width " + std::to_string(width_pixels) +
                           " pixels outside [64, 16384]");
  const auto speed_it = particles.scalars.find("speed");
  const bool bad =
      particles.z.size() != particles.x.size() ||
      (speed_it != particles.scalars.end() && speed_it->second.size() != particles.x.size());
  if (comm.any(bad))
    throw core::InputError(
        "render_snapshot: particles need as many z and scalars[\"speed\"] values as x values "
        "on every rank");
  std::vector<double> mine;
  mine.reserve(3 * particles.x.size());
  for (std::size_t n = 0; n < particles.x.size(); ++n)
    mine.insert(mine.end(), {particles.x[n], particles.z[n],
                             speed_it != particles.scalars.end() ? speed_it->second[n] : 0.0});
  const auto points = gather_to_root(comm, mine);
  const auto solid_lines = unpack(gather_to_root(comm, pack(solids)));
  const auto obstacle_lines = unpack(gather_to_root(comm, pack(obstacles)));

  std::string error;
  if (comm.is_root()) {
    // Layout: margin, tank, margin, colour bar, room for its ticks.
    const int margin = std::max(4, width_pixels / 50);
    const int bar_w = std::max(8, width_pixels / 40);
    const int plot_w = width_pixels - 3 * margin - bar_w - std::max(3, bar_w / 3);
    const double scale = plot_w / length;
    const int plot_h = std::max(1, static_cast<int>(std::lround(height * scale)));
    Image img(width_pixels, plot_h + 2 * margin);
    auto to_pixel = [&](const core::Vec2& v) {
      return Pixel{margin + (v.x - tank.lo.x) * scale, margin + (tank.hi.z - v.z) * scale};
    };
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t m = 2; m < points.size(); m += 3) {
      lo = std::min(lo, points[m]);
      hi = std::max(hi, points[m]);
    }
    if (points.empty()) lo = hi = 0.0;
    // s = (speed - min) / (max - min), the colormap coordinate.
    const double range = hi > lo ? hi - lo : 1.0;
    const double radius = std::max(0.8, plot_w / 600.0);
    for (std::size_t m = 0; m + 2 < points.size(); m += 3)
      img.draw_disc(to_pixel({points[m], points[m + 1]}), radius,
                    colormap((points[m + 2] - lo) / range));
    const Rgb dark{64, 64, 64};
    auto draw = [&](const std::vector<std::vector<core::Vec2>>& lines, Rgb fill) {
      for (const auto& l : lines) {
        std::vector<Pixel> px;
        for (const auto& v : l) px.push_back(to_pixel(v));
        img.draw_polyline(px, dark, true, true, fill);
      }
    };
    draw(obstacle_lines, {150, 150, 150});
    draw(solid_lines, {210, 210, 210});
    // Tank walls.
    img.draw_polyline({to_pixel(tank.lo), to_pixel({tank.hi.x, tank.lo.z}), to_pixel(tank.hi),
                       to_pixel({tank.lo.x, tank.hi.z})},
                      dark, true);
    img.draw_colour_bar(2 * margin + plot_w, margin, bar_w, plot_h, dark);
    char lo_s[32], hi_s[32];
    std::snprintf(lo_s, sizeof lo_s, "%.17g", lo);
    std::snprintf(hi_s, sizeof hi_s, "%.17g", hi);
    try {
      img.write_png(png_path, {{"speed_min", lo_s}, {"speed_max", hi_s}, {"Software", "picdem"}});
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

}  // namespace picdem::io

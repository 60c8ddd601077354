// The standard picture of a state (render_snapshot), drawn with Cairo by rank 0 from gathered
// data, and the reader of such pictures (read_png). Cairo stays inside this file.
#include "picdem/io/render.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::io {
namespace {

// viridis at s = 0, 1/8, ..., 1 (8-bit sRGB).
constexpr Rgb viridis[9] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},
                            {44, 114, 142}, {33, 144, 140}, {39, 173, 129},
                            {93, 200, 99},  {170, 220, 50}, {253, 231, 37}};

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

// The largest of 1, 2, 5 times a power of ten that is at most x (x > 0).
double nice_below(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (const double k : {5.0, 2.0, 1.0})
    if (k * p <= x * (1.0 + 1e-12)) return k * p;
  return p;
}

using Cairo = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void set_rgb(cairo_t* cr, Rgb c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

constexpr Rgb ink{40, 40, 40};

// Text with its reference point at (x, y): align 0 left, 0.5 centred, 1 right; the vertical
// centre of the digits at y when middle is set, the baseline otherwise.
void text(cairo_t* cr, const std::string& s, double x, double y, double align, bool middle) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align * e.x_advance, middle ? y - (e.y_bearing + 0.5 * e.height) : y);
  cairo_show_text(cr, s.c_str());
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, decimals), v);
  return buf;
}

void draw_outlines(cairo_t* cr, const SnapshotLayout& L,
                   const std::vector<std::vector<core::Vec2>>& lines, Rgb fill, double line_w) {
  for (const auto& l : lines) {
    if (l.empty()) continue;
    cairo_new_path(cr);
    for (const auto& v : l) cairo_line_to(cr, L.px(v.x), L.py(v.z));
    cairo_close_path(cr);
    set_rgb(cr, fill);
    cairo_fill_preserve(cr);
    set_rgb(cr, ink);
    cairo_set_line_width(cr, line_w);
    cairo_stroke(cr);
  }
}

// The colour bar: a linear gradient through the colour map's samples, framed, ticks every
// nice step of [0, speed_max] labelled in m/s, and the quantity's name along it.
void draw_colour_bar(cairo_t* cr, const SnapshotLayout& L, double speed_max) {
  const double x0 = L.bar_x0, y0 = L.bar_y0, w = L.bar_w, h = L.bar_h, f = L.font_size;
  cairo_pattern_t* grad = cairo_pattern_create_linear(0.0, y0 + h, 0.0, y0);
  for (int k = 0; k < 9; ++k)
    cairo_pattern_add_color_stop_rgb(grad, k / 8.0, viridis[k].r / 255.0, viridis[k].g / 255.0,
                                     viridis[k].b / 255.0);
  cairo_rectangle(cr, x0, y0, w, h);
  cairo_set_source(cr, grad);
  cairo_fill(cr);
  cairo_pattern_destroy(grad);
  set_rgb(cr, ink);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, x0 - 0.5, y0 - 0.5, w + 1.0, h + 1.0);
  cairo_stroke(cr);
  const double step = nice_below(speed_max / 4.0);
  const int decimals = static_cast<int>(-std::floor(std::log10(step) + 1e-9));
  double label_w = 0.0;
  cairo_set_font_size(cr, f);
  for (int k = 0; k * step <= speed_max * (1.0 + 1e-9); ++k) {
    const double y = y0 + h - k * step / speed_max * h;
    cairo_move_to(cr, x0 + w, y);
    cairo_line_to(cr, x0 + w + 0.45 * f, y);
    cairo_stroke(cr);
    const std::string s = fixed(k * step, decimals);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    label_w = std::max(label_w, e.x_advance);
    text(cr, s, x0 + w + 0.7 * f, y, 0.0, true);
  }
  cairo_save(cr);
  cairo_translate(cr, x0 + w + 0.9 * f + label_w + 0.4 * f, y0 + 0.5 * h);
  cairo_rotate(cr, -M_PI / 2.0);
  text(cr, "speed [m/s]", 0.0, 0.0, 0.5, true);
  cairo_restore(cr);
}

// A bar of a round length (about a fifth of the tank) under the tank's left end, labelled.
void draw_scale_bar(cairo_t* cr, const SnapshotLayout& L, double tank_length, double y) {
  const double len = nice_below(tank_length / 4.0);
  const double x0 = L.plot_x0, x1 = x0 + len * L.scale, tick = 0.35 * L.font_size;
  set_rgb(cr, ink);
  cairo_set_line_width(cr, std::max(1.5, L.font_size / 8.0));
  cairo_move_to(cr, x0, y - tick);
  cairo_line_to(cr, x0, y + tick);
  cairo_move_to(cr, x0, y);
  cairo_line_to(cr, x1, y);
  cairo_move_to(cr, x1, y - tick);
  cairo_line_to(cr, x1, y + tick);
  cairo_stroke(cr);
  std::string label;
  if (len >= 1.0)
    label = fixed(len, 0) + " m";
  else if (len >= 0.01)
    label = fixed(len * 100.0, 0) + " cm";
  else
    label = fixed(len * 1000.0, len >= 1e-3 ? 0 : 3) + " mm";
  text(cr, label, x1 + 0.6 * L.font_size, y, 0.0, true);
}

}  // namespace

Rgb colormap(double s) {
  if (!(s > 0.0)) s = 0.0;  // also maps NaN to the low end
  if (s > 1.0) s = 1.0;
  const double f = s * 8.0;
  const int n = std::min(7, static_cast<int>(f));
  const double w = f - n;
  auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround((1.0 - w) * a + w * b));
  };
  const Rgb &a = viridis[n], &b = viridis[n + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

SnapshotLayout snapshot_layout(const core::Box2& tank, int width_pixels) {
  const double length = tank.hi.x - tank.lo.x, height = tank.hi.z - tank.lo.z;
  if (!(length > 0.0 && height > 0.0))
    throw core::InputError("render_snapshot: the tank box must have positive length and height");
  if (width_pixels < 200 || width_pixels > 16384)
    throw core::InputError("render_snapshot: width " + std::to_string(width_pixels) +
                           " pixels outside [200, 16384]");
  SnapshotLayout L;
  const double w = width_pixels;
  L.font_size = std::max(9.0, w / 64.0);
  const double f = L.font_size;
  const int margin = static_cast<int>(std::lround(std::max(4.0, w / 60.0)));
  L.bar_w = static_cast<int>(std::lround(std::max(8.0, w / 45.0)));
  // Right of the tank: gap, bar, ticks and their labels (up to five characters), axis name.
  const int right = margin + L.bar_w + static_cast<int>(std::lround(4.5 * f));
  const int plot_w = width_pixels - 2 * margin - right;
  L.scale = plot_w / length;
  const int plot_h = std::max(1, static_cast<int>(std::lround(height * L.scale)));
  L.plot_x0 = margin;
  L.plot_y0 = margin + static_cast<int>(std::lround(1.6 * f));
  L.bar_x0 = L.plot_x0 + plot_w + margin;
  L.bar_y0 = L.plot_y0;
  L.bar_h = std::max(plot_h, static_cast<int>(std::lround(6.0 * f)));
  L.width = width_pixels;
  L.height = L.plot_y0 + L.bar_h + static_cast<int>(std::lround(2.2 * f)) + margin / 2;
  L.tank_lo_x = tank.lo.x;
  L.tank_hi_z = tank.hi.z;
  return L;
}

namespace {

// Draws the gathered state on rank 0; returns an error text or empty.
std::string draw_snapshot(const std::string& png_path, const core::Box2& tank,
                          const std::vector<double>& points,
                          const std::vector<std::vector<core::Vec2>>& solids,
                          const std::vector<std::vector<core::Vec2>>& obstacles,
                          const SnapshotStyle& style) {
  const SnapshotLayout L = snapshot_layout(tank, style.width_pixels);
  const double f = L.font_size, line_w = std::max(1.0, L.width / 700.0);
  const double plot_w = (tank.hi.x - tank.lo.x) * L.scale;
  const double plot_h = (tank.hi.z - tank.lo.z) * L.scale;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, L.width, L.height);
  Cairo cr(cairo_create(surface), &cairo_destroy);
  cairo_surface_destroy(surface);  // the context holds its own reference
  cairo_t* c = cr.get();
  cairo_set_source_rgb(c, 1.0, 1.0, 1.0);
  cairo_paint(c);
  cairo_select_font_face(c, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  // Particles, clipped to the tank: s = speed / speed_max on the colour map.
  cairo_save(c);
  cairo_rectangle(c, L.plot_x0, L.plot_y0, plot_w, plot_h);
  cairo_clip(c);
  const double r = std::max(0.6, style.particle_radius * L.scale);
  for (std::size_t m = 0; m + 2 < points.size(); m += 3) {
    cairo_arc(c, L.px(points[m]), L.py(points[m + 1]), r, 0.0, 2.0 * M_PI);
    set_rgb(c, colormap(points[m + 2] / style.speed_max));
    cairo_fill(c);
  }
  cairo_restore(c);
  draw_outlines(c, L, obstacles, {150, 150, 150}, line_w);
  draw_outlines(c, L, solids, {215, 215, 215}, line_w);
  // Tank walls, drawn outside the tank so that they hide no particle.
  set_rgb(c, ink);
  cairo_set_line_width(c, 2.0 * line_w);
  cairo_rectangle(c, L.plot_x0 - line_w, L.plot_y0 - line_w, plot_w + 2.0 * line_w,
                  plot_h + 2.0 * line_w);
  cairo_stroke(c);
  draw_colour_bar(c, L, style.speed_max);
  draw_scale_bar(c, L, tank.hi.x - tank.lo.x, L.plot_y0 + plot_h + 1.1 * f);
  cairo_set_font_size(c, 1.1 * f);
  const double baseline = L.plot_y0 - 0.5 * f;
  cairo_select_font_face(c, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  text(c, style.title, L.plot_x0, baseline, 0.0, false);
  cairo_select_font_face(c, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  char when[96];
  std::snprintf(when, sizeof when, "t = %.3f s   step %lld", style.time, style.step);
  text(c, when, L.plot_x0 + plot_w, baseline, 1.0, false);
  cairo_surface_flush(cairo_get_target(c));
  const cairo_status_t st = cairo_surface_write_to_png(cairo_get_target(c), png_path.c_str());
  if (st != CAIRO_STATUS_SUCCESS)
    return "render_snapshot: cannot write '" + png_path + "': " + cairo_status_to_string(st);
  return {};
}

}  // namespace

void render_snapshot(const core::Comm& comm, const std::string& png_path, const core::Box2& tank,
                     const PointSet& particles, const Polylines& solids, const Polylines& obstacles,
                     const SnapshotStyle& style) {
  core::ScopedTimer timer("io: picture");
  snapshot_layout(tank, style.width_pixels);  // throws on every rank for a bad tank or width
  if (!(style.speed_max > 0.0) || !std::isfinite(style.speed_max))
    throw core::InputError("render_snapshot: speed_max must be positive, not " +
                           std::to_string(style.speed_max));
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
  if (comm.is_root())
    error = draw_snapshot(png_path, tank, points, solid_lines, obstacle_lines, style);
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

RgbImage read_png(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> owner(s,
                                                                           &cairo_surface_destroy);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
    throw core::InputError("read_png: cannot read '" + path +
                           "': " + cairo_status_to_string(cairo_surface_status(s)));
  const cairo_format_t format = cairo_image_surface_get_format(s);
  if (format != CAIRO_FORMAT_RGB24 && format != CAIRO_FORMAT_ARGB32)
    throw core::InputError("read_png: '" + path + "' is neither RGB nor RGBA 8-bit");
  RgbImage img;
  img.width = cairo_image_surface_get_width(s);
  img.height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  img.pixels.reserve(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::uint32_t v;  // native-endian 0xAARRGGBB, colour premultiplied by alpha
      std::memcpy(&v, data + static_cast<std::size_t>(y) * stride + 4 * x, 4);
      const unsigned a = format == CAIRO_FORMAT_ARGB32 ? v >> 24 : 255u;
      auto un = [a](unsigned c) {
        return static_cast<std::uint8_t>(a == 0 ? 0 : std::min(255u, (c * 255u + a / 2) / a));
      };
      img.pixels.push_back({un((v >> 16) & 255u), un((v >> 8) & 255u), un(v & 255u)});
    }
  return img;
}

}  // namespace picdem::io

#pragma once
// The standard picture of a state (a PNG snapshot drawn with Cairo by rank 0), a reader for such
// pictures, and the movie of a run's pictures (ffmpeg, or an animated GIF through Python's PIL).
// No Cairo type appears here: Cairo stays inside render.cpp and png_read.cpp.
#include <cstdint>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/io/frame_writer.hpp"

namespace picdem::io {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  constexpr bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
  constexpr bool operator!=(const Rgb& o) const { return !(*this == o); }
};

/// The perceptual colour map (viridis, sampled at 9 points and interpolated linearly in sRGB) at s
/// in [0, 1]; s is clamped (NaN maps to 0).
Rgb colormap(double s);

/// What a snapshot shows besides the state.
struct SnapshotStyle {
  int width_pixels = 1000;       ///< picture width; the height follows the tank's aspect ratio
  double speed_max = 1.0;        ///< speed [m/s] at the top of the colour bar; 0 at the bottom
  double particle_radius = 0.0;  ///< disc radius [m] of a particle (at least 0.6 pixel)
  std::string title;             ///< e.g. the case name, top left
  double time = 0.0;             ///< simulated time [s], top right
  long long step = 0;            ///< step number, top right after the time
};

/// Where things land in a snapshot of `tank` at `width_pixels` (pixel (0, 0) is the top-left
/// corner of the top-left pixel; y grows downwards).
struct SnapshotLayout {
  int width = 0, height = 0;
  int plot_x0 = 0, plot_y0 = 0;  ///< pixel corner of the tank's (lo.x, hi.z) corner
  double scale = 0.0;            ///< pixels per metre
  int bar_x0 = 0, bar_y0 = 0, bar_w = 0, bar_h = 0;  ///< colour bar: speed_max at the top
  double font_size = 0.0;                            ///< pixels
  /// The pixel position of the point v of the tank's plane.
  double px(double x) const { return plot_x0 + (x - tank_lo_x) * scale; }
  double py(double z) const { return plot_y0 + (tank_hi_z - z) * scale; }
  double tank_lo_x = 0.0, tank_hi_z = 0.0;
};

/// Throws core::InputError for an empty tank or a width outside [64, 16384].
SnapshotLayout snapshot_layout(const core::Box2& tank, int width_pixels);

/// The standard picture of a state, written by rank 0 from data gathered from all ranks: the
/// particles as discs coloured by scalars["speed"] over the fixed range [0, speed_max] (faster
/// ones take the top colour), obstacles and solids filled grey and outlined, the tank walls, a
/// colour bar with ticks labelled in m/s, a length scale bar, the title, the time and the step.
/// Collective; throws core::InputError (on every rank) for bad input or an unwritable file.
void render_snapshot(const core::Comm& comm, const std::string& png_path, const core::Box2& tank,
                     const PointSet& particles, const Polylines& solids, const Polylines& obstacles,
                     const SnapshotStyle& style);

/// A decoded 8-bit RGB picture (alpha dropped), row-major from the top-left pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
  Rgb at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Reads a PNG file (through Cairo's reader). Throws core::InputError if it cannot be read.
RgbImage read_png(const std::string& path);

/// What make_movie did: `path` of the movie, or empty with the reason in `message`.
struct MovieResult {
  std::string path;
  std::string message;
};

/// Joins the pictures `directory`/frame_NNNNNN.png with NNNNNN <= last_step, in step order, into
/// `directory`/movie.mp4 (H.264 through the program `ffmpeg`, searched on PATH unless a path) at
/// `frames_per_second`; without ffmpeg into movie.gif through python3 with PIL. Never throws for
/// a missing or failing encoder: the result says what happened. Not collective (call on one rank).
MovieResult make_movie(const std::string& directory, long long last_step, double frames_per_second,
                       const std::string& ffmpeg = "ffmpeg",
                       const std::string& python = "/usr/bin/python3");

}  // namespace picdem::io

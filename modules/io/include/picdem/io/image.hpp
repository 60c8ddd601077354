#pragma once
// A small RGB raster canvas and its PNG encoder (zlib deflate + CRC-32, no other library).
// Pixel (0, 0) is the top-left corner; x grows to the right, y downwards.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace picdem::io {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  constexpr bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
  constexpr bool operator!=(const Rgb& o) const { return !(*this == o); }
};

/// A point in pixel coordinates (fractional positions allowed).
struct Pixel {
  double x = 0.0, y = 0.0;
};

/// The perceptual colormap (viridis, sampled at 9 points and interpolated linearly) at s in
/// [0, 1]; s is clamped.
Rgb colormap(double s);

class Image {
 public:
  /// Throws std::invalid_argument unless 0 < width, height <= 65536.
  Image(int width, int height, Rgb background = {255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  /// Out-of-range pixels are ignored by set() (drawing clips) and rejected by get().
  void set(int x, int y, Rgb c);
  Rgb get(int x, int y) const;
  void fill(Rgb c);

  /// A line from a to b, `thickness` pixels wide (Bresenham for thickness 1).
  void draw_line(Pixel a, Pixel b, Rgb c, int thickness = 1);
  /// Every pixel whose centre lies within `radius` of `centre` (at least the nearest pixel).
  void draw_disc(Pixel centre, double radius, Rgb c);
  /// A polyline; closed joins the last point to the first; filled paints its interior (even-odd
  /// rule, pixel centres) and then the outline in `c`, the interior in `fill_colour`.
  void draw_polyline(const std::vector<Pixel>& points, Rgb c, bool closed = false,
                     bool filled = false, Rgb fill_colour = {200, 200, 200});
  /// A vertical colour bar in the box [x0, x0 + w) x [y0, y0 + h): colormap(0) at the bottom,
  /// colormap(1) at the top, framed in `frame`, with tick marks at both ends on the right side.
  void draw_colour_bar(int x0, int y0, int w, int h, Rgb frame = {64, 64, 64});

  /// Writes an 8-bit RGB PNG. `text` entries become tEXt chunks (keyword, value), e.g. the
  /// numbers the colour bar stands for. Throws core::InputError if the file cannot be written.
  void write_png(const std::string& path,
                 const std::vector<std::pair<std::string, std::string>>& text = {}) const;

  const std::vector<std::uint8_t>& pixels() const { return rgb_; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgb_;  // row-major, 3 bytes a pixel
};

}  // namespace picdem::io

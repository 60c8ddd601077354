#include "picdem/io/image.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "picdem/core/error.hpp"

namespace picdem::io {

Rgb colormap(double s) {
  // viridis at s = 0, 1/8, ..., 1 (8-bit sRGB).
  static const Rgb table[9] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},
                               {44, 114, 142}, {33, 144, 140}, {39, 173, 129},
                               {93, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if (!(s > 0.0)) s = 0.0;  // also maps NaN to the low end
  if (s > 1.0) s = 1.0;
  const double f = s * 8.0;
  const int n = std::min(7, static_cast<int>(f));
  const double w = f - n;
  auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround((1.0 - w) * a + w * b));
  };
  const Rgb &a = table[n], &b = table[n + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

Image::Image(int width, int height, Rgb background) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
    throw std::invalid_argument("Image: size " + std::to_string(width) + " x " +
                                std::to_string(height) + " outside 1..65536");
  rgb_.resize(static_cast<std::size_t>(width) * height * 3);
  fill(background);
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const std::size_t p = (static_cast<std::size_t>(y) * width_ + x) * 3;
  rgb_[p] = c.r;
  rgb_[p + 1] = c.g;
  rgb_[p + 2] = c.b;
}

Rgb Image::get(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    throw std::out_of_range("Image::get: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") outside the image");
  const std::size_t p = (static_cast<std::size_t>(y) * width_ + x) * 3;
  return {rgb_[p], rgb_[p + 1], rgb_[p + 2]};
}

void Image::fill(Rgb c) {
  for (std::size_t p = 0; p < rgb_.size(); p += 3) {
    rgb_[p] = c.r;
    rgb_[p + 1] = c.g;
    rgb_[p + 2] = c.b;
  }
}

void Image::draw_line(Pixel a, Pixel b, Rgb c, int thickness) {
  // Bresenham between the pixels holding a and b.
  int x0 = static_cast<int>(std::floor(a.x)), y0 = static_cast<int>(std::floor(a.y));
  const int x1 = static_cast<int>(std::floor(b.x)), y1 = static_cast<int>(std::floor(b.y));
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  while (true) {
    if (thickness <= 1)
      set(x0, y0, c);
    else
      draw_disc({x0 + 0.5, y0 + 0.5}, 0.5 * thickness, c);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x0 += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y0 += sy;
    }
  }
}

void Image::draw_disc(Pixel centre, double radius, Rgb c) {
  const int xa = static_cast<int>(std::floor(centre.x - radius));
  const int xb = static_cast<int>(std::ceil(centre.x + radius));
  const int ya = static_cast<int>(std::floor(centre.y - radius));
  const int yb = static_cast<int>(std::ceil(centre.y + radius));
  const double r2 = radius * radius;
  for (int y = std::max(ya, 0); y <= std::min(yb, height_ - 1); ++y)
    for (int x = std::max(xa, 0); x <= std::min(xb, width_ - 1); ++x) {
      const double ex = x + 0.5 - centre.x, ey = y + 0.5 - centre.y;
      if (ex * ex + ey * ey <= r2) set(x, y, c);
    }
  set(static_cast<int>(std::floor(centre.x)), static_cast<int>(std::floor(centre.y)), c);
}

void Image::draw_polyline(const std::vector<Pixel>& points, Rgb c, bool closed, bool filled,
                          Rgb fill_colour) {
  const std::size_t n = points.size();
  if (n == 0) return;
  if (filled && n >= 3) {
    // Even-odd scanline fill at pixel centres; an edge counts on [min y, max y).
    std::vector<double> xs;
    for (int y = 0; y < height_; ++y) {
      const double yc = y + 0.5;
      xs.clear();
      for (std::size_t e = 0; e < n; ++e) {
        const Pixel& p = points[e];
        const Pixel& q = points[(e + 1) % n];
        if ((p.y <= yc && q.y > yc) || (q.y <= yc && p.y > yc))
          xs.push_back(p.x + (yc - p.y) / (q.y - p.y) * (q.x - p.x));
      }
      std::sort(xs.begin(), xs.end());
      for (std::size_t m = 0; m + 1 < xs.size(); m += 2) {
        // Pixels whose centre x + 0.5 lies in [xs[m], xs[m+1]).
        const int xa = static_cast<int>(std::ceil(xs[m] - 0.5));
        const int xb = static_cast<int>(std::ceil(xs[m + 1] - 0.5));
        for (int x = std::max(xa, 0); x < std::min(xb, width_); ++x) set(x, y, fill_colour);
      }
    }
  }
  if (n == 1)
    set(static_cast<int>(std::floor(points[0].x)), static_cast<int>(std::floor(points[0].y)), c);
  for (std::size_t e = 0; e + 1 < n; ++e) draw_line(points[e], points[e + 1], c);
  if (closed && n > 2) draw_line(points[n - 1], points[0], c);
}

void Image::draw_colour_bar(int x0, int y0, int w, int h, Rgb frame) {
  if (w <= 0 || h <= 0) return;
  for (int row = 0; row < h; ++row) {
    const Rgb c = colormap(h > 1 ? static_cast<double>(h - 1 - row) / (h - 1) : 0.0);
    for (int x = x0; x < x0 + w; ++x) set(x, y0 + row, c);
  }
  const double l = x0 - 0.5, r = x0 + w + 0.5, t = y0 - 0.5, b = y0 + h + 0.5;
  draw_polyline({{l, t}, {r, t}, {r, b}, {l, b}}, frame, true);
  // Tick marks for the minimum (bottom) and the maximum (top).
  const int tick = std::max(3, w / 3);
  draw_line({r, t}, {r + tick, t}, frame);
  draw_line({r, b}, {r + tick, b}, frame);
}

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.push_back(static_cast<std::uint8_t>(v >> 24));
  out.push_back(static_cast<std::uint8_t>(v >> 16));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
  out.push_back(static_cast<std::uint8_t>(v));
}

// length, type, data, CRC-32 of type + data.
void put_chunk(std::vector<std::uint8_t>& out, const char type[4],
               const std::vector<std::uint8_t>& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  const uLong crc = crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start));
  put_u32(out, static_cast<std::uint32_t>(crc));
}

}  // namespace

void Image::write_png(const std::string& path,
                      const std::vector<std::pair<std::string, std::string>>& text) const {
  std::vector<std::uint8_t> png = {137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<std::uint8_t> ihdr;
  put_u32(ihdr, static_cast<std::uint32_t>(width_));
  put_u32(ihdr, static_cast<std::uint32_t>(height_));
  // bit depth 8, colour type 2 (RGB), deflate, filter method 0, no interlace.
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  put_chunk(png, "IHDR", ihdr);
  for (const auto& [key, value] : text) {
    if (key.empty() || key.size() > 79)
      throw std::invalid_argument("PNG text keyword '" + key + "' must have 1..79 characters");
    std::vector<std::uint8_t> t(key.begin(), key.end());
    t.push_back(0);
    t.insert(t.end(), value.begin(), value.end());
    put_chunk(png, "tEXt", t);
  }
  // Every scanline: filter type 0 (none), then the row's RGB bytes.
  const std::size_t row = static_cast<std::size_t>(width_) * 3;
  std::vector<std::uint8_t> raw;
  raw.reserve((row + 1) * height_);
  for (int y = 0; y < height_; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), rgb_.begin() + y * row, rgb_.begin() + (y + 1) * row);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> idat(size);
  if (compress2(idat.data(), &size, raw.data(), static_cast<uLong>(raw.size()),
                Z_DEFAULT_COMPRESSION) != Z_OK)
    throw std::runtime_error("PNG: zlib compress2 failed for '" + path + "'");
  idat.resize(size);
  put_chunk(png, "IDAT", idat);
  put_chunk(png, "IEND", {});
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw core::InputError("cannot open PNG file '" + path + "' for writing");
  const bool ok = std::fwrite(png.data(), 1, png.size(), f) == png.size();
  if (std::fclose(f) != 0 || !ok) throw core::InputError("cannot write PNG file '" + path + "'");
}

}  // namespace picdem::io

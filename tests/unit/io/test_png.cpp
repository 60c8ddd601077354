// PNG: decode what Image::write_png wrote (chunk CRCs, inflate of IDAT, pixel values) and the
// standard snapshot picture.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/io/frame_writer.hpp"
#include "picdem/io/image.hpp"

namespace {

using picdem::io::Image;
using picdem::io::Pixel;
using picdem::io::Rgb;

struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::map<std::string, std::string> text;
  std::vector<std::string> chunk_order;
};

std::uint32_t be32(const std::uint8_t* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
         p[3];
}

// A strict decoder for what the writer produces: 8-bit RGB, filter 0 on every row.
Decoded decode(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> f((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
  Decoded d;
  const std::uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  EXPECT_GE(f.size(), 8u);
  EXPECT_TRUE(std::equal(sig, sig + 8, f.begin()));
  std::vector<std::uint8_t> idat;
  std::size_t p = 8;
  while (p + 12 <= f.size()) {
    const std::uint32_t len = be32(&f[p]);
    EXPECT_LE(p + 12 + len, f.size());
    const std::string type(f.begin() + p + 4, f.begin() + p + 8);
    const std::uint8_t* data = &f[p + 8];
    const uLong crc = crc32(0L, &f[p + 4], len + 4);
    EXPECT_EQ(crc, be32(&f[p + 8 + len])) << "CRC of chunk " << type;
    d.chunk_order.push_back(type);
    if (type == "IHDR") {
      d.width = static_cast<int>(be32(data));
      d.height = static_cast<int>(be32(data + 4));
      EXPECT_EQ(data[8], 8);  // bit depth
      EXPECT_EQ(data[9], 2);  // RGB
    } else if (type == "IDAT") {
      idat.insert(idat.end(), data, data + len);
    } else if (type == "tEXt") {
      const std::string s(data, data + len);
      d.text[s.substr(0, s.find('\0'))] = s.substr(s.find('\0') + 1);
    }
    p += 12 + len;
  }
  EXPECT_EQ(p, f.size());
  const std::size_t row = 3 * static_cast<std::size_t>(d.width);
  std::vector<std::uint8_t> raw((row + 1) * d.height);
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &size, idat.data(), idat.size()), Z_OK);
  EXPECT_EQ(size, raw.size());
  for (int y = 0; y < d.height; ++y) {
    EXPECT_EQ(raw[y * (row + 1)], 0) << "filter byte of row " << y;
    d.rgb.insert(d.rgb.end(), raw.begin() + y * (row + 1) + 1, raw.begin() + (y + 1) * (row + 1));
  }
  return d;
}

Rgb at(const Decoded& d, int x, int y) {
  const std::size_t p = (static_cast<std::size_t>(y) * d.width + x) * 3;
  return {d.rgb[p], d.rgb[p + 1], d.rgb[p + 2]};
}

std::string name(const std::string& base) {
  return base + "_np" + std::to_string(picdem::core::Comm().size()) + ".png";
}

TEST(Png, ColormapEndsAndMonotoneLightness) {
  EXPECT_EQ(picdem::io::colormap(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(picdem::io::colormap(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(picdem::io::colormap(-3.0), picdem::io::colormap(0.0));
  EXPECT_EQ(picdem::io::colormap(0.5), (Rgb{33, 144, 140}));
  // Perceptual ordering: luma grows along the map.
  double prev = -1;
  for (int n = 0; n <= 64; ++n) {
    const Rgb c = picdem::io::colormap(n / 64.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, prev) << n;
    prev = luma;
  }
}

TEST(Png, DecodesWithKnownPixels) {
  const picdem::core::Comm comm;
  if (!comm.is_root()) return;  // a serial object: rank 0 checks it
  Image img(37, 21, {255, 255, 255});
  img.set(0, 0, {1, 2, 3});
  img.set(36, 20, {250, 0, 7});
  img.draw_line({2.5, 10.5}, {30.5, 10.5}, {0, 0, 255});
  img.draw_disc({10.0, 5.0}, 2.0, {255, 0, 0});
  // A filled triangle with corners on pixel boundaries.
  img.draw_polyline({{20, 2}, {34, 2}, {34, 9}}, {0, 0, 0}, true, true, {0, 200, 0});
  img.set(-1, 5, {9, 9, 9});  // clipped, no effect
  img.write_png(name("png_basic"), {{"key", "value 1"}});
  const Decoded d = decode(name("png_basic"));
  ASSERT_EQ(d.width, 37);
  ASSERT_EQ(d.height, 21);
  EXPECT_EQ(d.chunk_order.front(), "IHDR");
  EXPECT_EQ(d.chunk_order.back(), "IEND");
  EXPECT_EQ(d.text.at("key"), "value 1");
  EXPECT_EQ(at(d, 0, 0), (Rgb{1, 2, 3}));
  EXPECT_EQ(at(d, 36, 20), (Rgb{250, 0, 7}));
  EXPECT_EQ(at(d, 1, 1), (Rgb{255, 255, 255}));
  for (int x = 2; x <= 30; ++x) EXPECT_EQ(at(d, x, 10), (Rgb{0, 0, 255})) << x;
  EXPECT_EQ(at(d, 31, 10), (Rgb{255, 255, 255}));
  // Disc of radius 2 around (10, 5): pixel centres within 2.
  EXPECT_EQ(at(d, 9, 4), (Rgb{255, 0, 0}));
  EXPECT_EQ(at(d, 11, 4), (Rgb{255, 0, 0}));      // centre (11.5, 4.5): distance 1.58
  EXPECT_EQ(at(d, 11, 3), (Rgb{255, 255, 255}));  // centre (11.5, 3.5): distance 2.12 > 2
  EXPECT_EQ(at(d, 12, 6), (Rgb{255, 255, 255}));
  // Triangle interior (below the edge from (20,2) to (34,9) is outside): (32, 4) is inside.
  EXPECT_EQ(at(d, 32, 4), (Rgb{0, 200, 0}));
  EXPECT_EQ(at(d, 22, 7), (Rgb{255, 255, 255}));
  // Decoded image == canvas, byte for byte.
  EXPECT_EQ(d.rgb, img.pixels());
}

TEST(Png, BadSizeAndUnwritablePath) {
  EXPECT_THROW(Image(0, 5), std::invalid_argument);
  Image img(4, 4);
  EXPECT_THROW(img.write_png("/nonexistent_dir_picdem/x.png"), picdem::core::InputError);
}

TEST(Png, SnapshotGathersEveryRanksParticles) {
  const picdem::core::Comm comm;
  // Tank [0, 2] x [0, 1]; each rank contributes one particle; the last one is the fastest.
  picdem::io::PointSet p;
  const int r = comm.rank(), size = comm.size();
  p.x = {0.2 + 0.5 * r};
  p.z = {0.5};
  p.scalars["speed"] = {1.0 + r};
  if (r == 0) {  // and the slowest one
    p.x.push_back(0.2);
    p.z.push_back(0.8);
    p.scalars["speed"].push_back(0.0);
  }
  picdem::io::Polylines solids, obstacles;
  if (r == 0) {
    solids.lines = {{{1.6, 0.1}, {1.9, 0.1}, {1.9, 0.4}, {1.6, 0.4}}};
    solids.body_id = {0};
  }
  picdem::io::render_snapshot(comm, name("png_snapshot"), {{0.0, 0.0}, {2.0, 1.0}}, p, solids,
                              obstacles, 400);
  comm.barrier();
  if (!comm.is_root()) return;
  const Decoded d = decode(name("png_snapshot"));
  // Layout from render_snapshot: margin 8, bar 10, plot width 400 - 24 - 10 - 3 = 363.
  const double scale = 363.0 / 2.0;
  auto px = [&](double x, double z, int& i, int& j) {
    i = static_cast<int>(8 + x * scale);
    j = static_cast<int>(8 + (1.0 - z) * scale);
  };
  EXPECT_EQ(d.width, 400);
  EXPECT_EQ(d.height, static_cast<int>(std::lround(scale)) + 16);
  EXPECT_EQ(std::stod(d.text.at("speed_min")), 0.0);
  EXPECT_EQ(std::stod(d.text.at("speed_max")), static_cast<double>(size));
  int i, j;
  px(0.2, 0.8, i, j);
  EXPECT_EQ(at(d, i, j), picdem::io::colormap(0.0));
  px(0.2, 0.5, i, j);
  EXPECT_EQ(at(d, i, j), picdem::io::colormap(1.0 / size));
  px(0.2 + 0.5 * (size - 1), 0.5, i, j);
  EXPECT_EQ(at(d, i, j), picdem::io::colormap(1.0));
  px(1.75, 0.25, i, j);
  EXPECT_EQ(at(d, i, j), (Rgb{210, 210, 210}));  // inside the solid
  px(1.0, 1.0, i, j);
  EXPECT_EQ(at(d, i, j), (Rgb{64, 64, 64}));  // top tank wall
  // Colour bar: top row maximum colour, bottom row minimum colour.
  const int bar_x = 2 * 8 + 363 + 5;
  EXPECT_EQ(at(d, bar_x, 8), picdem::io::colormap(1.0));
  EXPECT_EQ(at(d, bar_x, d.height - 9), picdem::io::colormap(0.0));
}

}  // namespace

namespace {

TEST(Png, SnapshotRejectsMismatchedSpeedOnEveryRank) {
  const picdem::core::Comm comm;
  picdem::io::PointSet p;
  p.x = {0.5};
  p.z = {0.5};
  if (comm.rank() == comm.size() - 1) p.scalars["speed"] = {1.0, 2.0};  // one rank is wrong
  EXPECT_THROW(
      picdem::io::render_snapshot(comm, name("png_bad"), {{0.0, 0.0}, {1.0, 1.0}}, p, {}, {}, 200),
      picdem::core::InputError);
}

}  // namespace

// PNG snapshots: render_snapshot's pictures decoded again (read_png, libpng through Cairo) and
// checked pixel by pixel against the layout, the colour map and the fixed colour range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/io/render.hpp"

namespace {

using picdem::core::Box2;
using picdem::core::Comm;
using picdem::io::colormap;
using picdem::io::read_png;
using picdem::io::render_snapshot;
using picdem::io::Rgb;
using picdem::io::RgbImage;
using picdem::io::snapshot_layout;
using picdem::io::SnapshotStyle;

const Box2 tank{{0.0, 0.0}, {2.0, 1.0}};

std::string name(const std::string& base) {
  return base + "_np" + std::to_string(Comm().size()) + ".png";
}

int max_channel_diff(Rgb a, Rgb b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

bool white(Rgb c) {
  return c == Rgb{255, 255, 255};
}

SnapshotStyle style(int width, double speed_max) {
  SnapshotStyle s;
  s.width_pixels = width;
  s.speed_max = speed_max;
  s.particle_radius = 0.05;
  s.title = "test case";
  s.time = 0.25;
  s.step = 40;
  return s;
}

TEST(Png, ColormapEndsAndMonotoneLightness) {
  EXPECT_EQ(colormap(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(colormap(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(colormap(-3.0), colormap(0.0));
  EXPECT_EQ(colormap(std::nan("")), colormap(0.0));
  EXPECT_EQ(colormap(0.5), (Rgb{33, 144, 140}));
  // Perceptual ordering: luma grows along the map.
  double prev = -1;
  for (int n = 0; n <= 64; ++n) {
    const Rgb c = colormap(n / 64.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, prev) << n;
    prev = luma;
  }
}

// Every row inside the bar has the colour of its height: s = (bottom - row centre) / bar height.
TEST(Png, ColourBarFollowsTheColormap) {
  const Comm comm;
  render_snapshot(comm, name("png_bar"), tank, {}, {}, {}, style(600, 2.0));
  if (!comm.is_root()) return;
  const RgbImage img = read_png(name("png_bar"));
  const auto L = snapshot_layout(tank, 600);
  ASSERT_GT(L.bar_h, 100);
  int worst = 0;
  for (int y = L.bar_y0; y < L.bar_y0 + L.bar_h; ++y) {
    const double s = (L.bar_y0 + L.bar_h - (y + 0.5)) / L.bar_h;
    for (int x = L.bar_x0; x < L.bar_x0 + L.bar_w; ++x)
      worst = std::max(worst, max_channel_diff(img.at(x, y), colormap(s)));
  }
  EXPECT_LE(worst, 2) << "largest channel difference from the colour map in the bar";
  // The frame just outside the bar is dark.
  EXPECT_LT(img.at(L.bar_x0 - 1, L.bar_y0 + L.bar_h / 2).g, 80);
  EXPECT_LT(img.at(L.bar_x0 + L.bar_w, L.bar_y0 + L.bar_h / 2).g, 80);
}

// A square solid [0.5, 0.9] x [0.2, 0.6] m: its outline's first and last dark pixels along the
// row and the column through its centre lie within a pixel of the edges' pixel positions.
TEST(Png, SolidLandsAtItsPixels) {
  const Comm comm;
  picdem::io::Polylines solids;
  if (comm.rank() == comm.size() - 1)
    solids.lines = {{{0.5, 0.2}, {0.9, 0.2}, {0.9, 0.6}, {0.5, 0.6}}}, solids.body_id = {7};
  render_snapshot(comm, name("png_solid"), tank, {}, solids, {}, style(800, 1.0));
  if (!comm.is_root()) return;
  const RgbImage img = read_png(name("png_solid"));
  const auto L = snapshot_layout(tank, 800);
  const int row = static_cast<int>(L.py(0.4)), col = static_cast<int>(L.px(0.7));
  int first = -1, last = -1;
  for (int x = static_cast<int>(L.px(0.05)); x < static_cast<int>(L.px(1.95)); ++x)
    if (!white(img.at(x, row))) {
      if (first < 0) first = x;
      last = x;
    }
  EXPECT_NEAR(first + 0.5, L.px(0.5), 1.0);
  EXPECT_NEAR(last + 0.5, L.px(0.9), 1.0);
  int top = -1, bottom = -1;
  for (int y = static_cast<int>(L.py(0.95)); y < static_cast<int>(L.py(0.05)); ++y)
    if (!white(img.at(col, y))) {
      if (top < 0) top = y;
      bottom = y;
    }
  EXPECT_NEAR(top + 0.5, L.py(0.6), 1.0);
  EXPECT_NEAR(bottom + 0.5, L.py(0.2), 1.0);
  EXPECT_EQ(img.at(col, row), (Rgb{215, 215, 215}));  // filled
  EXPECT_EQ(img.width, 800);
  EXPECT_EQ(img.height, L.height);
}

// Two frames of one run: a patch at 0.5 m/s keeps its colour, colormap(0.5 / speed_max),
// whatever the other particles do (the range does not follow the frame's extremes).
TEST(Png, FixedRangeGivesTheSameColoursInEveryFrame) {
  const Comm comm;
  std::vector<RgbImage> frames;
  for (const double other : {2.0, 0.1}) {
    picdem::io::PointSet p;
    if (comm.is_root()) {
      for (int i = -2; i <= 2; ++i)
        for (int j = -2; j <= 2; ++j) {
          p.x.push_back(1.5 + 0.04 * i);
          p.z.push_back(0.3 + 0.04 * j);
          p.scalars["speed"].push_back(0.5);
        }
      p.x.push_back(0.3);
      p.z.push_back(0.7);
      p.scalars["speed"].push_back(other);
    } else {
      p.scalars["speed"];
    }
    auto s = style(600, 1.0);
    s.time = other;
    const std::string file = name("png_range_" + std::to_string(frames.size()));
    render_snapshot(comm, file, tank, p, {}, {}, s);
    if (comm.is_root()) frames.push_back(read_png(file));
  }
  if (!comm.is_root()) return;
  const auto L = snapshot_layout(tank, 600);
  const int x = static_cast<int>(L.px(1.5)), y = static_cast<int>(L.py(0.3));
  EXPECT_EQ(frames[0].at(x, y), frames[1].at(x, y));
  EXPECT_LE(max_channel_diff(frames[0].at(x, y), colormap(0.5)), 1);
  const int xo = static_cast<int>(L.px(0.3)), yo = static_cast<int>(L.py(0.7));
  EXPECT_LE(max_channel_diff(frames[0].at(xo, yo), colormap(1.0)), 1);  // 2 m/s: the top colour
  EXPECT_LE(max_channel_diff(frames[1].at(xo, yo), colormap(0.1)), 1);
}

TEST(Png, SizeFollowsTheWidth) {
  const Comm comm;
  for (const int w : {300, 1000, 1500}) {
    render_snapshot(comm, name("png_width"), tank, {}, {}, {}, style(w, 1.0));
    if (!comm.is_root()) continue;
    const RgbImage img = read_png(name("png_width"));
    const auto L = snapshot_layout(tank, w);
    EXPECT_EQ(img.width, w);
    EXPECT_EQ(img.height, L.height);
    // The tank keeps its 2:1 aspect ratio within a pixel.
    EXPECT_NEAR(L.py(0.0) - L.py(1.0), 0.5 * (L.px(2.0) - L.px(0.0)), 1.0);
  }
}

// The title is drawn: the header band above the tank changes with it and has dark text pixels.
TEST(Png, TitleAndTimeAreWritten) {
  const Comm comm;
  auto s = style(600, 1.0);
  render_snapshot(comm, name("png_title"), tank, {}, {}, {}, s);
  s.title.clear();
  render_snapshot(comm, name("png_untitled"), tank, {}, {}, {}, s);
  if (!comm.is_root()) return;
  const RgbImage a = read_png(name("png_title")), b = read_png(name("png_untitled"));
  const auto L = snapshot_layout(tank, 600);
  int dark_a = 0, dark_b = 0, dark_right = 0;
  for (int y = 0; y < L.plot_y0 - 2; ++y) {
    for (int x = 0; x < L.width / 3; ++x) {
      dark_a += a.at(x, y).r < 100;
      dark_b += b.at(x, y).r < 100;
    }
    for (int x = L.width / 2; x < L.bar_x0; ++x) dark_right += b.at(x, y).r < 100;
  }
  EXPECT_GT(dark_a, 50) << "the title's pixels";
  EXPECT_EQ(dark_b, 0) << "no title, no text on the left";
  EXPECT_GT(dark_right, 50) << "the time's pixels";
}

TEST(Png, SnapshotGathersEveryRanksParticles) {
  const Comm comm;
  // Each rank contributes one particle at its own place and speed r / size.
  picdem::io::PointSet p;
  const int r = comm.rank(), size = comm.size();
  p.x = {0.3 + 0.4 * r};
  p.z = {0.5};
  p.scalars["speed"] = {static_cast<double>(r) / size};
  render_snapshot(comm, name("png_gather"), tank, p, {}, {}, style(600, 1.0));
  if (!comm.is_root()) return;
  const RgbImage img = read_png(name("png_gather"));
  const auto L = snapshot_layout(tank, 600);
  for (int k = 0; k < size; ++k) {
    const Rgb c = img.at(static_cast<int>(L.px(0.3 + 0.4 * k)), static_cast<int>(L.py(0.5)));
    EXPECT_LE(max_channel_diff(c, colormap(static_cast<double>(k) / size)), 1) << "rank " << k;
  }
}

TEST(Png, BadInputIsRejectedOnEveryRank) {
  const Comm comm;
  picdem::io::PointSet p;
  p.x = {0.5};
  p.z = {0.5};
  if (comm.rank() == comm.size() - 1) p.scalars["speed"] = {1.0, 2.0};  // one rank is wrong
  EXPECT_THROW(render_snapshot(comm, name("png_bad"), tank, p, {}, {}, style(400, 1.0)),
               picdem::core::InputError);
  EXPECT_THROW(render_snapshot(comm, name("png_bad"), tank, {}, {}, {}, style(100, 1.0)),
               picdem::core::InputError);
  EXPECT_THROW(render_snapshot(comm, name("png_bad"), tank, {}, {}, {}, style(400, 0.0)),
               picdem::core::InputError);
  EXPECT_THROW(
      render_snapshot(comm, "/nonexistent_dir_picdem/x.png", tank, {}, {}, {}, style(400, 1.0)),
      picdem::core::InputError);
  EXPECT_THROW(read_png("/nonexistent_dir_picdem/x.png"), picdem::core::InputError);
}

TEST(Movie, MissingEncoderGivesAMessage) {
  const Comm comm;
  if (!comm.is_root()) return;  // make_movie is not collective
  const std::string dir = "movie_missing_np" + std::to_string(comm.size());
  std::filesystem::create_directories(dir);
  render_snapshot(Comm(MPI_COMM_SELF), dir + "/frame_000000.png", tank, {}, {}, {},
                  style(300, 1.0));
  const auto m =
      picdem::io::make_movie(dir, 100, 10.0, "/nonexistent/ffmpeg", "/nonexistent/python3");
  EXPECT_TRUE(m.path.empty());
  EXPECT_NE(m.message.find("neither '/nonexistent/ffmpeg'"), std::string::npos) << m.message;
  const auto none = picdem::io::make_movie(dir + "/nothing_here", 100, 10.0);
  EXPECT_TRUE(none.path.empty());
  EXPECT_NE(none.message.find("no pictures"), std::string::npos) << none.message;
}

}  // namespace

// The movie of a run's pictures: ffmpeg's mp4 holds every picture up to the last step, in step
// order (frames counted by ffprobe); without ffmpeg the GIF through python3 + PIL does.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "picdem/core/comm.hpp"
#include "picdem/io/render.hpp"

namespace {

namespace fs = std::filesystem;

// The standard output of a command (its first line).
std::string output_of(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return out.substr(0, out.find('\n'));
}

// Five pictures at steps 0, 10, ..., 40 and one at step 100 (after the run's last step 40).
std::string make_frames(const std::string& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const long long step : {0LL, 10LL, 20LL, 30LL, 40LL, 100LL}) {
    picdem::io::SnapshotStyle s;
    s.width_pixels = 301;  // odd: the encoder pads to even sizes
    s.speed_max = 1.0;
    s.step = step;
    char file[64];
    std::snprintf(file, sizeof file, "/frame_%06lld.png", step);
    picdem::io::render_snapshot(picdem::core::Comm(MPI_COMM_SELF), dir + file,
                                {{0.0, 0.0}, {1.0, 0.5}}, {}, {}, {}, s);
  }
  return dir;
}

TEST(Movie, Mp4HoldsEveryFrameUpToTheLastStep) {
  if (!picdem::core::Comm().is_root()) return;
  const std::string dir = make_frames("movie_mp4");
  const auto m = picdem::io::make_movie(dir, 40, 10.0);
  const int height = picdem::io::snapshot_layout({{0.0, 0.0}, {1.0, 0.5}}, 301).height;
  ASSERT_EQ(m.path, dir + "/movie.mp4") << m.message;
  EXPECT_EQ(output_of("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                      "stream=nb_read_frames,width,height -of csv=p=0 " +
                      m.path),
            "302," + std::to_string(height + height % 2) + ",5");
  EXPECT_FALSE(fs::exists(dir + "/.movie_frames"));
}

TEST(Movie, GifWithoutFfmpeg) {
  if (!picdem::core::Comm().is_root()) return;
  const std::string dir = make_frames("movie_gif");
  const auto m = picdem::io::make_movie(dir, 40, 10.0, "/nonexistent/ffmpeg");
  ASSERT_EQ(m.path, dir + "/movie.gif") << m.message;
  EXPECT_EQ(output_of("/usr/bin/python3 -c \"from PIL import Image; im = Image.open('" + m.path +
                      "'); print(im.n_frames, im.size[0])\""),
            "5 301");
}

}  // namespace

// The movie of a run's pictures: ffmpeg (H.264 mp4) when present, an animated GIF through
// python3 + PIL otherwise, a message (never an exception) when neither can be run.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <system_error>

#include "picdem/io/render.hpp"

extern char** environ;

namespace picdem::io {
namespace {

namespace fs = std::filesystem;

// The program's path: itself if it holds a '/', else the first executable match on PATH.
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t a = 0; a <= dirs.size();) {
    const std::size_t b = std::min(dirs.find(':', a), dirs.size());
    const std::string candidate = (b > a ? dirs.substr(a, b - a) : ".") + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    a = b + 1;
  }
  return "";
}

// Runs argv[0] with the arguments (no shell), its standard output and error to /dev/null;
// returns the exit status, or -1 if it could not be started or did not exit normally.
int run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

// The pictures frame_<step>.png with step <= last_step, in step order.
std::vector<fs::path> frames(const std::string& directory, long long last_step) {
  std::vector<std::pair<long long, fs::path>> found;
  const std::regex name("frame_([0-9]+)\\.png");
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(directory, ec)) {
    std::smatch m;
    const std::string file = e.path().filename().string();
    if (!std::regex_match(file, m, name)) continue;
    const long long step = std::stoll(m[1].str());
    if (step <= last_step) found.emplace_back(step, e.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& f : found) out.push_back(fs::absolute(f.second));
  return out;
}

// The GIF: PIL joins the listed pictures (palette per frame), looping.
MovieResult gif(const std::string& python, const std::vector<fs::path>& list, const fs::path& out,
                double fps) {
  const fs::path listing = out.parent_path() / ".movie_frames.txt";
  if (FILE* f = std::fopen(listing.c_str(), "w")) {
    for (const auto& p : list) std::fprintf(f, "%s\n", p.c_str());
    std::fclose(f);
  } else {
    return {"", "no movie: cannot write " + listing.string()};
  }
  const std::string script =
      "import sys\nfrom PIL import Image\n"
      "names = open(sys.argv[1]).read().splitlines()\n"
      "im = [Image.open(n).convert('P', palette=Image.Palette.ADAPTIVE) for n in names]\n"
      "im[0].save(sys.argv[2], save_all=True, append_images=im[1:], loop=0,"
      " duration=int(round(1000 / float(sys.argv[3]))))\n";
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.17g", fps);
  const int rc = run({python, "-c", script, listing.string(), out.string(), rate});
  std::error_code ec;
  fs::remove(listing, ec);
  if (rc != 0) return {"", "no movie: '" + python + "' with PIL failed to write " + out.string()};
  return {out.string(), std::to_string(list.size()) + " pictures, animated GIF (no ffmpeg)"};
}

}  // namespace

MovieResult make_movie(const std::string& directory, long long last_step, double frames_per_second,
                       const std::string& ffmpeg, const std::string& python) {
  const auto list = frames(directory, last_step);
  if (list.empty()) return {"", "no movie: no pictures frame_*.png in " + directory};
  if (!(frames_per_second > 0.0)) return {"", "no movie: frames per second must be positive"};
  const std::string encoder = find_program(ffmpeg);
  if (encoder.empty()) {
    const std::string py = find_program(python);
    if (!py.empty() && run({py, "-c", "import PIL.Image"}) == 0)
      return gif(py, list, fs::path(directory) / "movie.gif", frames_per_second);
    return {"", "no movie: neither '" + ffmpeg + "' nor '" + python +
                    "' with PIL was found (Debian: apt-get install ffmpeg, or python3-pil)"};
  }
  // ffmpeg reads numbered names: links 000000.png, 000001.png, ... in a scratch folder.
  const fs::path scratch = fs::path(directory) / ".movie_frames";
  std::error_code ec;
  fs::remove_all(scratch, ec);
  fs::create_directories(scratch, ec);
  for (std::size_t n = 0; n < list.size() && !ec; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.png", n);
    fs::create_symlink(list[n], scratch / name, ec);
  }
  if (ec) return {"", "no movie: cannot prepare " + scratch.string() + ": " + ec.message()};
  const fs::path out = fs::path(directory) / "movie.mp4";
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.17g", frames_per_second);
  // Even width and height (yuv420p needs them), H.264 for every player.
  const int rc = run({encoder, "-y", "-loglevel", "error", "-framerate", rate, "-i",
                      (scratch / "%06d.png").string(), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                      "-c:v", "libx264", "-pix_fmt", "yuv420p", out.string()});
  fs::remove_all(scratch, ec);
  if (rc != 0)
    return {"", "no movie: '" + encoder + "' failed (exit status " + std::to_string(rc) + ")"};
  return {out.string(), std::to_string(list.size()) + " pictures, H.264 by ffmpeg"};
}

}  // namespace picdem::io

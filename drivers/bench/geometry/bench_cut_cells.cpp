// Cut-cell build time on a 1024^2 grid: 100 circles of 20 cells per diameter, 100 polygons of
// 12 and of 64 vertices of the same size. Prints milliseconds (best of several repetitions);
// the empty-grid cost (filling the window's arrays) is printed apart and subtracted per solid.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <random>

#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/polygon.hpp"

using namespace picdem::geometry;

namespace {

/// Best CPU time of this thread in ms (the machine is shared: wall time would count others' work).
double best_ms(const std::function<void()>& f, int reps) {
  auto now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
  };
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const double t0 = now();
    f();
    best = std::min(best, now() - t0);
  }
  return best;
}

ShapePtr regular(int n, double R) {
  std::vector<Vec2> v;
  for (int j = 0; j < n; ++j)
    v.push_back({R * std::cos(2 * M_PI * j / n), R * std::sin(2 * M_PI * j / n)});
  return std::make_shared<Polygon>(v);
}

}  // namespace

int main() {
  const int n = 1024;
  const double h = 1.0 / n;
  const GridWindow window{{0.0, 0.0}, h, {0, n, 0, n}};
  const double R = 10.0 * h;  // 20 cells per diameter
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // 1000 sites on a 32 x 32 lattice (32 cells apart), jittered, random rotation; the first 100
  // are spread over the whole grid.
  std::vector<Pose> poses;
  for (int j = 0; j < 1024; ++j) {
    const int a = (j * 331) % 1024;  // scatter the first hundred
    poses.push_back({{(a % 32 + 0.4 + 0.2 * u(rng)) / 32.0, (a / 32 + 0.4 + 0.2 * u(rng)) / 32.0},
                     2 * M_PI * u(rng)});
  }
  const CutCellOptions opt;
  const int reps = 7;
  build_cut_cells(window, {}, {}, opt);  // warm-up: first-touch page faults
  const double empty = best_ms([&] { build_cut_cells(window, {}, {}, opt); }, reps);
  std::printf(
      "cut cells on a %d^2 grid (whole grid as one window), best of %d runs, thread CPU time\n", n,
      reps);
  std::printf("fixed cost, no solids (allocating and filling the window's arrays): %.2f ms\n",
              empty);
  std::printf("%-9s %12s %12s %22s %9s\n", "solids", "100: ms", "1000: ms", "ms per solid (slope)",
              "pieces");
  const struct {
    const char* name;
    ShapePtr shape;
  } cases[] = {{"circles", std::make_shared<Circle>(R)},
               {"12-gons", regular(12, R)},
               {"64-gons", regular(64, R)}};
  for (const auto& c : cases) {
    double t[2];
    std::size_t pieces = 0;
    for (int m = 0; m < 2; ++m) {
      std::vector<SolidPlacement> solids;
      for (int j = 0; j < (m == 0 ? 100 : 1000); ++j) solids.push_back({j, c.shape, poses[j]});
      t[m] =
          best_ms([&] { pieces = build_cut_cells(window, solids, {}, opt).pieces.size(); }, reps);
    }
    std::printf("%-9s %12.2f %12.2f %22.4f %9zu\n", c.name, t[0], t[1], (t[1] - t[0]) / 900.0,
                pieces);
  }
  return 0;
}

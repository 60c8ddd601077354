// A scene for the rank-invariance tests of cut cells and of the face velocities beside bodies:
// random disks and polygons (3 to 11 vertices, some overlapping) over [0, 1] x [0, 0.8], and a
// perforated fall pipe with a funnel across the middle, so that bodies, holes and walls straddle
// the ranks' cut lines on 2 and 3 ranks of a 64 x 48 grid.
#pragma once

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/cut_cells.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::test_support {

/// 40 solids (even j: disks, odd j: polygons) of id j, radii and sizes up to `size` + 0.01 m.
inline std::vector<geometry::SolidPlacement> random_solids(unsigned seed, double size,
                                                           int max_extra_vertices) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<geometry::SolidPlacement> s;
  for (int j = 0; j < 40; ++j) {
    geometry::ShapePtr shape;
    if (j % 2 == 0) {
      shape = std::make_shared<geometry::Circle>(0.01 + size * u(rng));
    } else {
      std::vector<core::Vec2> v;
      const int n = 3 + j % max_extra_vertices;
      for (int q = 0; q < n; ++q) {
        const double phi = 2 * M_PI * (q + 0.7 * u(rng)) / n, r = 0.02 + 0.8 * size * u(rng);
        v.push_back({r * std::cos(phi), r * std::sin(phi)});
      }
      shape = std::make_shared<geometry::Polygon>(v);
    }
    s.push_back({j, shape, {{0.05 + 0.9 * u(rng), 0.05 + 0.7 * u(rng)}, 6.0 * u(rng)}});
  }
  return s;
}

/// The perforated pipe (inner width 0.1 m at x = 0.5, z from 0.2 to 0.6, funnel above, 0.03 m
/// holes every 0.1 m) as one obstacle.
inline std::vector<geometry::Obstacle> perforated_pipe() {
  geometry::FallPipe pipe;
  pipe.centre_x = 0.5;
  pipe.inner_width = 0.1;
  pipe.wall_thickness = 0.02;
  pipe.bottom = 0.2;
  pipe.top = 0.6;
  pipe.funnel_top_width = 0.3;
  pipe.funnel_height = 0.1;
  pipe.hole_size = 0.03;
  pipe.hole_spacing = 0.1;
  return {{"pipe", geometry::fall_pipe_polygons(pipe, "pipe")}};
}

}  // namespace picdem::test_support

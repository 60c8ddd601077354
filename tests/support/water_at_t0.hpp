#pragma once
// The water's area at t = 0 of a case seeded as one box (water/<name>/x, z) around solids:
// the box less the disks' parts inside it (the cylinder dam breaks' volume baseline, issue 14).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/solid_state.hpp"

namespace picdem::test_support {

/// Area of the disk (centre c, radius r) inside the box [0, W] x [0, H]: the chord's length
/// clipped to [0, H], integrated over x = c.x + r sin(phi) (midpoint rule in phi, 4,000 points:
/// error below 1e-9 of the disk's area).
inline double disk_area_in_box(core::Vec2 c, double r, double W, double H) {
  const double lo = std::asin(std::clamp(-c.x / r, -1.0, 1.0)),
               hi = std::asin(std::clamp((W - c.x) / r, -1.0, 1.0));
  const int n = 4000;
  const double dphi = (hi - lo) / n;
  double area = 0.0;
  for (int q = 0; q < n; ++q) {
    const double phi = lo + (q + 0.5) * dphi, half = r * std::cos(phi);
    const double chord = std::min(c.z + half, H) - std::max(c.z - half, 0.0);
    area += std::max(chord, 0.0) * half * dphi;  // dx = r cos(phi) dphi
  }
  return area;
}

/// The box water/<region> less the parts of the disks of radius r at `solids` inside it.
inline double water_at_t0(const core::Params& params, const std::string& region,
                          const std::vector<core::SolidState>& solids, double r) {
  const auto xs = params.reals("water/" + region + "/x"),
             zs = params.reals("water/" + region + "/z");
  const double W = xs.at(1) - xs.at(0), H = zs.at(1) - zs.at(0);
  double v0 = W * H;
  for (const auto& s : solids) v0 -= disk_area_in_box(s.x - core::Vec2{xs[0], zs[0]}, r, W, H);
  return v0;
}

}  // namespace picdem::test_support

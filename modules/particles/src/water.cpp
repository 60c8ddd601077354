// The water at t = 0 (water.hpp).
#include "picdem/particles/water.hpp"

#include <algorithm>
#include <sstream>

namespace picdem::particles {

namespace {

// Each entry of `water` inside the tank, with a non-empty block.
void check_water(const core::Params& p, std::vector<std::string>& errors) {
  const auto o = p.reals("grid/origin");
  const double x0 = o[0], z0 = o[1];
  const double x1 = x0 + p.real("grid/length"), z1 = z0 + p.real("grid/height");
  // Particles are seeded one spacing apart: a region thinner than that may hold none of them (a
  // level typed in mm as m, a block of zero width), and the run would go on without that water.
  const double spacing = p.real("grid/cell_size") /
                         static_cast<double>(std::max(
                             1LL, static_cast<long long>(p.integer("particles/per_cell_1d"))));
  auto too_thin = [&](const std::string& name, const char* what, double size) {
    std::ostringstream m;
    m.precision(10);
    m << "water/" << name << ": " << what << " " << size
      << " m, less than one particle spacing (grid/cell_size / particles/per_cell_1d = " << spacing
      << " m): it would seed no water; allowed: at least one spacing";
    errors.push_back(m.str());
  };
  for (const auto& name : p.sublist_names("water")) {
    const auto w = p.sub("water/" + name);
    std::ostringstream msg;
    msg.precision(10);
    if (w.string("type") == "box") {
      const auto x = w.reals("x"), z = w.reals("z");
      if (!(x[0] < x[1]) || !(z[0] < z[1])) {
        msg << "water/" << name << ": x = [" << x[0] << ", " << x[1] << "], z = [" << z[0] << ", "
            << z[1] << "] is empty; give [min, max] with min < max";
        errors.push_back(msg.str());
      } else if (x[0] < x0 || x[1] > x1 || z[0] < z0 || z[1] > z1) {
        msg << "water/" << name << ": the block x = [" << x[0] << ", " << x[1] << "], z = [" << z[0]
            << ", " << z[1] << "] reaches outside the tank x in [" << x0 << ", " << x1
            << "], z in [" << z0 << ", " << z1 << "]";
        errors.push_back(msg.str());
      } else if (std::min(x[1] - x[0], z[1] - z[0]) < spacing) {
        too_thin(name, "the block is", std::min(x[1] - x[0], z[1] - z[0]));
      }
    } else {
      const double z = w.real("z");
      if (z <= z0 || z > z1) {
        msg << "key 'water/" << name << "/z' = " << z << " is not allowed: the level must lie in ("
            << z0 << ", " << z1 << "], inside the tank";
        errors.push_back(msg.str());
      } else if (z - z0 < spacing) {
        too_thin(name, "the water below the level is", z - z0);
      }
    }
  }
}

}  // namespace

void declare_water_parameters(core::ParamSchema& s) {
  auto& water = s.family("water", "Where the fluid is at t = 0 (their union; none: a dry run).");
  auto& box = water.variant("box", "an axis-aligned block of water");
  box.reals("x", {0.0, 0.1}, "[x_min, x_max] of the block [m]").size(2, 2);
  box.reals("z", {0.0, 0.1}, "[z_min, z_max] of the block [m]").size(2, 2);
  auto& level = water.variant("level", "all of the tank below a still-water level");
  level.real("z", 0.1, "still-water level [m]");
  s.check(check_water);
}

WaterRegions::WaterRegions(const core::Params& params) {
  for (const auto& name : params.sublist_names("water")) {
    const auto w = params.sub("water/" + name);
    Region r;
    r.box = w.string("type") == "box";
    if (r.box) {
      const auto x = w.reals("x"), z = w.reals("z");
      r.x0 = x[0], r.x1 = x[1], r.z0 = z[0], r.z1 = z[1];
    } else {
      r.z1 = w.real("z");
    }
    regions_.push_back(r);
  }
}

bool WaterRegions::contains(core::Vec2 c) const {
  for (const auto& w : regions_) {
    if (w.box) {
      if (c.x >= w.x0 && c.x <= w.x1 && c.z >= w.z0 && c.z <= w.z1) return true;
    } else if (c.z <= w.z1) {
      return true;
    }
  }
  return false;
}

ParticleSet seed_water(const grid::Decomposition& d, const ParticleConfig& config,
                       const WaterRegions& water, const std::function<bool(core::Vec2)>& in_body) {
  using core::Vec2;
  const auto wet = [&](Vec2 p) { return water.contains(p) && !(in_body && in_body(p)); };
  const double r = 0.5 * d.spec().h;
  auto ps = seed(
      d, config,
      [&](Vec2 c) {
        return water.contains(c) || water.contains(c + Vec2{r, r}) ||
               water.contains(c + Vec2{-r, r}) || water.contains(c + Vec2{r, -r}) ||
               water.contains(c + Vec2{-r, -r});
      },
      wet);
  std::vector<char> keep(ps.size());
  for (std::size_t n = 0; n < keep.size(); ++n) keep[n] = wet({ps.x[n], ps.z[n]});
  ps.keep_if(keep);
  return ps;
}

}  // namespace picdem::particles

// Placing a graded packing without overlap (doc/shapes.md, "graded_packing"): each solid is
// represented by its bounding circle, and two bounding circles, or a circle and a side of the
// box, are kept at least the gap apart, so the real boundaries are too. Random sequential
// addition fills a box; pouring drops each solid down a random column onto the floor or the
// solids already there.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "picdem/core/error.hpp"
#include "picdem/geometry/graded_packing.hpp"

namespace picdem::geometry {

PackingRandom::PackingRandom(std::uint64_t seed) : engine_(seed) {}

double PackingRandom::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

long long PackingRandom::integer(long long lo, long long hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<long long>(engine_() % span);
}

namespace {

struct Disk {
  Vec2 c;
  double r;
};

/// Bounding circles binned in square cells of side `cell` (at least the largest diameter plus
/// the gap), so every possible neighbour of a circle lies in the 3 x 3 cells around it.
class Bins {
 public:
  Bins(double x0, double z0, double cell) : x0_(x0), z0_(z0), cell_(cell) {}
  void add(const Disk& d) {
    disks_.push_back(d);
    bins_[key(ix(d.c.x), iz(d.c.z))].push_back(disks_.size() - 1);
  }
  /// True when the circle keeps `gap` (plus a rounding margin) to every circle placed.
  bool free(const Disk& d, double gap) const {
    const long long cx = ix(d.c.x), cz = iz(d.c.z);
    for (long long a = cx - 1; a <= cx + 1; ++a)
      for (long long b = cz - 1; b <= cz + 1; ++b) {
        const auto it = bins_.find(key(a, b));
        if (it == bins_.end()) continue;
        for (const std::size_t j : it->second) {
          const double reach = clearance(d.r, disks_[j].r, gap);
          if (core::norm2(d.c - disks_[j].c) < reach * reach) return false;
        }
      }
    return true;
  }
  /// Centre distance that keeps two circles `gap` apart, with a relative margin of 1e-9 so
  /// the rounding of later arithmetic never brings them closer than the gap.
  static double clearance(double ri, double rj, double gap) {
    return (ri + rj + gap) * (1.0 + 1e-9);
  }

 private:
  long long ix(double x) const { return static_cast<long long>(std::floor((x - x0_) / cell_)); }
  long long iz(double z) const { return static_cast<long long>(std::floor((z - z0_) / cell_)); }
  static long long key(long long a, long long b) { return a * 1000003LL + b; }
  double x0_, z0_, cell_;
  std::vector<Disk> disks_;
  std::unordered_map<long long, std::vector<std::size_t>> bins_;
};

/// Columns of width `cell` holding the bounding circles placed, for pouring.
class Columns {
 public:
  Columns(double x0, double cell) : x0_(x0), cell_(cell) {}
  void add(const Disk& d) { cols_[col(d.c.x)].push_back(d); }
  /// The centre height at which a circle of radius r dropped at x from far above first comes
  /// within the gap of a circle placed, or z_lowest (its centre on the floor).
  double landing(double x, double r, double gap, double z_lowest) const {
    double z = z_lowest;
    const long long c = col(x);
    for (long long a = c - 1; a <= c + 1; ++a) {
      const auto it = cols_.find(a);
      if (it == cols_.end()) continue;
      for (const Disk& d : it->second) {
        const double reach = Bins::clearance(r, d.r, gap), dx = x - d.c.x;
        if (std::fabs(dx) >= reach) continue;
        z = std::max(z, d.c.z + std::sqrt(reach * reach - dx * dx));
      }
    }
    return z;
  }

 private:
  long long col(double x) const { return static_cast<long long>(std::floor((x - x0_) / cell_)); }
  double x0_, cell_;
  std::unordered_map<long long, std::vector<Disk>> cols_;
};

[[noreturn]] void cannot_hold(const std::string& what, const PackingRegion& box, std::size_t k,
                              std::size_t n, const PackingItem& item, const std::string& why) {
  std::ostringstream m;
  m << what << ": the region [" << box.x0 << ", " << box.z0 << ", " << box.x1 << ", " << box.z1
    << "] cannot hold the requested solids (count or solid_fraction): placed " << k << " of " << n
    << ", then a solid of size d = " << item.size << " m " << why
    << "; lower count or solid_fraction, enlarge the region"
    << (box.pour ? "" : ", or use placement: pour (denser)");
  throw core::InputError(m.str());
}

}  // namespace

std::vector<PlacedShape> place_packing(std::vector<PackingItem> items, const PackingRegion& box,
                                       double gap, const std::string& what, PackingRandom& rng) {
  double r_max = 0.0;
  for (const auto& it : items) r_max = std::max(r_max, it.shape->bounding_radius());
  const double cell = 2.0 * Bins::clearance(r_max, r_max, gap);
  // box: largest first, the usual order of random sequential addition (denser, fewer misses)
  if (!box.pour)
    std::stable_sort(items.begin(), items.end(), [](const PackingItem& a, const PackingItem& b) {
      return a.shape->bounding_radius() > b.shape->bounding_radius();
    });
  Bins bins(box.x0, box.z0, cell);
  Columns columns(box.x0, cell);
  std::vector<PlacedShape> out;
  out.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const PackingItem& item = items[k];
    const double r = item.shape->bounding_radius(), margin = r + gap * (1.0 + 1e-9);
    const double xa = box.x0 + margin, xb = box.x1 - margin;
    const double za = box.z0 + margin, zb = box.z1 - margin;
    if (xa > xb || za > zb)
      cannot_hold(what, box, k, items.size(), item, "is wider than the region");
    bool found = false;
    Disk d{{0.0, 0.0}, r};
    if (box.pour) {
      double best = std::numeric_limits<double>::infinity();
      for (long long t = 0; t < box.drops; ++t) {
        const double x = xa + (xb - xa) * rng.uniform();
        const double z = columns.landing(x, r, gap, za);
        if (z <= zb && z < best) best = z, d.c = {x, z}, found = true;
      }
      if (!found) cannot_hold(what, box, k, items.size(), item, "lands above the region's top");
      columns.add(d);
    } else {
      for (long long t = 0; t < box.tries && !found; ++t) {
        d.c = {xa + (xb - xa) * rng.uniform(), za + (zb - za) * rng.uniform()};
        found = bins.free(d, gap);
      }
      if (!found) {
        std::ostringstream why;
        why << "found no free place in " << box.tries << " random tries";
        cannot_hold(what, box, k, items.size(), item, why.str());
      }
      bins.add(d);
    }
    out.push_back({item.shape, {d.c, item.theta}, item.density});
  }
  return out;
}

}  // namespace picdem::geometry

#pragma once
// Slow, independent reference computations for the cut-cell tests: cell by cell and face by
// face, in long double or exact rationals, with formulas unrelated to the library's line sweep.
#include <algorithm>
#include <cmath>
#include <vector>

#include "picdem/core/vec2.hpp"

namespace ref {

using LD = long double;
template <class T>
struct PT {
  T x, z;
};
using P = PT<LD>;

/// Area of the disc (centre 0, radius r) inside {X <= x, Z <= z}.
inline LD disc_quadrant(LD r, LD x, LD z) {
  auto s = [r](LD t) { return std::sqrt(std::max<LD>(0, r * r - t * t)); };
  // P(t) = integral of s = (t s + r^2 asin(t / r)) / 2
  auto Pint = [&](LD t) {
    return 0.5L * (t * s(t) + r * r * std::asin(std::clamp<LD>(t / r, -1, 1)));
  };
  const LD xm = std::clamp<LD>(x, -r, r);
  auto two_s = [&](LD a, LD b) {
    b = std::min(b, xm);
    return b > a ? 2 * (Pint(b) - Pint(a)) : 0.0L;
  };
  auto z_plus_s = [&](LD a, LD b) {
    b = std::min(b, xm);
    return b > a ? z * (b - a) + (Pint(b) - Pint(a)) : 0.0L;
  };
  if (z >= r) return two_s(-r, r);
  if (z <= -r) return 0;
  const LD w = std::sqrt(r * r - z * z);
  if (z >= 0) return two_s(-r, -w) + z_plus_s(-w, w) + two_s(w, r);
  return z_plus_s(-w, w);
}

inline LD disc_rect(LD cx, LD cz, LD r, LD x0, LD x1, LD z0, LD z1) {
  x0 -= cx, x1 -= cx, z0 -= cz, z1 -= cz;
  return disc_quadrant(r, x1, z1) - disc_quadrant(r, x0, z1) - disc_quadrant(r, x1, z0) +
         disc_quadrant(r, x0, z0);
}

/// Covered length of the face from (x, z0) to (x, z1) by the disc.
inline LD disc_vertical_face(LD cx, LD cz, LD r, LD x, LD z0, LD z1) {
  const LD d = x - cx;
  if (std::fabs(d) >= r) return 0;
  const LD s = std::sqrt(r * r - d * d);
  return std::max<LD>(0, std::min(z1, cz + s) - std::max(z0, cz - s));
}

/// Area of a simple polygon clipped to the rectangle (Sutherland-Hodgman, four half planes), in
/// the number type T (long double, or CGAL's exact rationals).
template <class T>
T polygon_rect(const std::vector<PT<T>>& poly, T x0, T x1, T z0, T z1) {
  using Pt = PT<T>;
  std::vector<Pt> cur = poly;
  for (int side = 0; side < 4 && !cur.empty(); ++side) {
    auto inside = [&](const Pt& p) -> bool {
      return side == 0 ? p.x >= x0 : side == 1 ? p.x <= x1 : side == 2 ? p.z >= z0 : p.z <= z1;
    };
    auto cut = [&](const Pt& a, const Pt& b) {
      T t;
      if (side < 2) {
        const T X = side == 0 ? x0 : x1;
        t = (X - a.x) / (b.x - a.x);
        return Pt{X, a.z + t * (b.z - a.z)};
      }
      const T Z = side == 2 ? z0 : z1;
      t = (Z - a.z) / (b.z - a.z);
      return Pt{a.x + t * (b.x - a.x), Z};
    };
    std::vector<Pt> out;
    for (std::size_t j = 0; j < cur.size(); ++j) {
      const Pt& a = cur[j];
      const Pt& b = cur[(j + 1) % cur.size()];
      const bool ia = inside(a), ib = inside(b);
      if (ia) out.push_back(a);
      if (ia != ib) out.push_back(cut(a, b));
    }
    cur.swap(out);
  }
  T a2 = 0;
  for (std::size_t j = 0; j < cur.size(); ++j) {
    const Pt& a = cur[j];
    const Pt& b = cur[(j + 1) % cur.size()];
    a2 += a.x * b.z - a.z * b.x;
  }
  return a2 / T(2);
}

template <class T>
bool polygon_contains(const std::vector<PT<T>>& poly, const T& x, const T& z) {
  using Pt = PT<T>;
  bool in = false;
  for (std::size_t j = 0, m = poly.size() - 1; j < poly.size(); m = j++) {
    const Pt& a = poly[j];
    const Pt& b = poly[m];
    if ((a.z > z) != (b.z > z) && x < (b.x - a.x) * (z - a.z) / (b.z - a.z) + a.x) in = !in;
  }
  return in;
}

/// Covered length of the vertical face (x, z0)-(x, z1) by the polygon (generic position).
template <class T>
T polygon_vertical_face(const std::vector<PT<T>>& poly, T x, T z0, T z1) {
  using Pt = PT<T>;
  std::vector<T> cuts{z0, z1};
  for (std::size_t j = 0; j < poly.size(); ++j) {
    const Pt& a = poly[j];
    const Pt& b = poly[(j + 1) % poly.size()];
    if ((a.x > x) != (b.x > x)) {
      const T z = a.z + (x - a.x) / (b.x - a.x) * (b.z - a.z);
      if (z > z0 && z < z1) cuts.push_back(z);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  T len = 0;
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
    if (polygon_contains(poly, x, T((cuts[j] + cuts[j + 1]) / T(2)))) len += cuts[j + 1] - cuts[j];
  }
  return len;
}

}  // namespace ref

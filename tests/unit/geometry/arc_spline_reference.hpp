#pragma once
// Independent references for shapes made of arcs and segments, in long double and written apart
// from the library: Green's theorem integrated by Gauss-Legendre quadrature piece by piece (the
// library sums a polygon fan and circular segments in closed form), the perimeter, the distance
// from a point to a piece, and the distance from a point to the true ellipse (Newton on the foot
// point's parameter).
#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "picdem/geometry/shape.hpp"

namespace arc_ref {

using LD = long double;
using picdem::geometry::Arc;
using picdem::geometry::BoundaryPiece;
using picdem::geometry::Segment;
using picdem::geometry::Vec2;

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from Chebyshev guesses).
inline void gauss_legendre(int n, std::vector<LD>& x, std::vector<LD>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  const LD pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < n; ++i) {
    LD t = std::cos(pi * (i + 0.75L) / (n + 0.5L)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      LD p0 = 1, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const LD p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1);
      const LD step = p1 / dp;
      t -= step;
      if (std::fabs(step) < 1e-19L) break;
    }
    x[i] = t;
    w[i] = 2 / ((1 - t * t) * dp * dp);
  }
}

struct Moments {
  LD area = 0, sx = 0, sz = 0, j_o = 0, perimeter = 0;  // j_o about the frame origin
};

/// A = 1/2 int (x dz - z dx), S_x = 1/2 int x^2 dz, S_z = -1/2 int z^2 dx,
/// J_o = 1/3 int (x^3 dz - z^3 dx), each piece by 32-point Gauss-Legendre.
inline Moments moments(const std::vector<BoundaryPiece>& loop) {
  std::vector<LD> gx, gw;
  gauss_legendre(32, gx, gw);
  Moments m;
  for (const auto& piece : loop) {
    for (std::size_t q = 0; q < gx.size(); ++q) {
      LD x, z, dx, dz, len;
      if (const auto* s = std::get_if<Segment>(&piece)) {
        const LD u = (gx[q] + 1) / 2;
        x = s->a.x + u * (LD(s->b.x) - s->a.x);
        z = s->a.z + u * (LD(s->b.z) - s->a.z);
        dx = (LD(s->b.x) - s->a.x) / 2;  // d/d(gx)
        dz = (LD(s->b.z) - s->a.z) / 2;
        len = std::sqrt(dx * dx + dz * dz);
      } else {
        const auto& a = std::get<Arc>(piece);
        const LD half = (LD(a.phi1) - a.phi0) / 2, phi = a.phi0 + half * (gx[q] + 1);
        x = a.centre.x + LD(a.radius) * std::cos(phi);
        z = a.centre.z + LD(a.radius) * std::sin(phi);
        dx = -LD(a.radius) * std::sin(phi) * half;
        dz = LD(a.radius) * std::cos(phi) * half;
        len = LD(a.radius) * half;
      }
      const LD w = gw[q];
      m.area += w * (x * dz - z * dx) / 2;
      m.sx += w * x * x * dz / 2;
      m.sz -= w * z * z * dx / 2;
      m.j_o += w * (x * x * x * dz - z * z * z * dx) / 3;
      m.perimeter += w * len;
    }
  }
  return m;
}

/// Distance from p to one piece.
inline LD distance(const BoundaryPiece& piece, LD px, LD pz) {
  if (const auto* s = std::get_if<Segment>(&piece)) {
    const LD rx = LD(s->b.x) - s->a.x, rz = LD(s->b.z) - s->a.z;
    const LD u =
        std::clamp(((px - s->a.x) * rx + (pz - s->a.z) * rz) / (rx * rx + rz * rz), LD(0), LD(1));
    return std::hypot(px - (s->a.x + u * rx), pz - (s->a.z + u * rz));
  }
  const auto& a = std::get<Arc>(piece);
  const LD dx = px - a.centre.x, dz = pz - a.centre.z;
  const LD two_pi = 6.283185307179586476925286766559L;
  LD phi = std::atan2(dz, dx) - a.phi0;
  phi -= two_pi * std::floor(phi / two_pi);
  if (phi <= LD(a.phi1) - a.phi0) return std::fabs(std::hypot(dx, dz) - a.radius);
  LD best = 1e300L;
  for (const LD e : {LD(a.phi0), LD(a.phi1)})
    best = std::min(best, std::hypot(px - a.centre.x - a.radius * std::cos(e),
                                     pz - a.centre.z - a.radius * std::sin(e)));
  return best;
}

inline LD distance(const std::vector<BoundaryPiece>& loop, LD px, LD pz) {
  LD best = 1e300L;
  for (const auto& piece : loop) best = std::min(best, distance(piece, px, pz));
  return best;
}

/// Distance from p (near the curve) to the ellipse x^2/a^2 + z^2/b^2 = 1: Newton on
/// f(t) = (E(t) - p) . E'(t) = 0 from the point's eccentric angle.
inline LD ellipse_distance(LD a, LD b, LD px, LD pz) {
  LD t = std::atan2(pz / b, px / a);
  for (int it = 0; it < 50; ++it) {
    const LD ex = a * std::cos(t), ez = b * std::sin(t);
    const LD dx = -a * std::sin(t), dz = b * std::cos(t);
    const LD f = (ex - px) * dx + (ez - pz) * dz;
    const LD fp = dx * dx + dz * dz - (ex - px) * ex - (ez - pz) * ez;
    const LD step = f / fp;
    t -= step;
    if (std::fabs(step) < 1e-18L) break;
  }
  return std::hypot(a * std::cos(t) - px, b * std::sin(t) - pz);
}

}  // namespace arc_ref

#pragma once
// Small value types shared by every module: 2D vectors in the (x, z) plane and index boxes.
#include <cmath>

namespace picdem::core {

/// A vector in the vertical (x, z) plane; z points up, gravity is (0, -g).
struct Vec2 {
  double x = 0.0;
  double z = 0.0;

  constexpr Vec2& operator+=(const Vec2& o) {
    x += o.x;
    z += o.z;
    return *this;
  }
  constexpr Vec2& operator-=(const Vec2& o) {
    x -= o.x;
    z -= o.z;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    z *= s;
    return *this;
  }
};

constexpr Vec2 operator+(Vec2 a, const Vec2& b) {
  return a += b;
}
constexpr Vec2 operator-(Vec2 a, const Vec2& b) {
  return a -= b;
}
constexpr Vec2 operator-(const Vec2& a) {
  return {-a.x, -a.z};
}
constexpr Vec2 operator*(double s, Vec2 a) {
  return a *= s;
}
constexpr Vec2 operator*(Vec2 a, double s) {
  return a *= s;
}
constexpr Vec2 operator/(Vec2 a, double s) {
  return {a.x / s, a.z / s};
}
constexpr bool operator==(const Vec2& a, const Vec2& b) {
  return a.x == b.x && a.z == b.z;
}
constexpr bool operator!=(const Vec2& a, const Vec2& b) {
  return !(a == b);
}

constexpr double dot(const Vec2& a, const Vec2& b) {
  return a.x * b.x + a.z * b.z;
}
/// Scalar 2D cross product a x b (the out-of-plane component).
constexpr double cross(const Vec2& a, const Vec2& b) {
  return a.x * b.z - a.z * b.x;
}
/// omega x r for an out-of-plane angular velocity omega.
constexpr Vec2 cross(double omega, const Vec2& r) {
  return {-omega * r.z, omega * r.x};
}
/// The vector rotated by +90 degrees.
constexpr Vec2 perp(const Vec2& a) {
  return {-a.z, a.x};
}
inline double norm(const Vec2& a) {
  return std::hypot(a.x, a.z);
}
constexpr double norm2(const Vec2& a) {
  return dot(a, a);
}
inline Vec2 rotate(const Vec2& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x - s * a.z, s * a.x + c * a.z};
}

/// An axis-aligned box of real coordinates [lo, hi].
struct Box2 {
  Vec2 lo;
  Vec2 hi;
  constexpr bool contains(const Vec2& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.z >= lo.z && p.z <= hi.z;
  }
  constexpr bool overlaps(const Box2& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
};

/// A half-open box of integer indices [i0, i1) x [k0, k1); i counts along x, k along z.
struct IndexBox {
  int i0 = 0, i1 = 0, k0 = 0, k1 = 0;

  constexpr int nx() const { return i1 > i0 ? i1 - i0 : 0; }
  constexpr int nz() const { return k1 > k0 ? k1 - k0 : 0; }
  constexpr long long size() const { return static_cast<long long>(nx()) * nz(); }
  constexpr bool empty() const { return nx() == 0 || nz() == 0; }
  constexpr bool contains(int i, int k) const { return i >= i0 && i < i1 && k >= k0 && k < k1; }
  constexpr IndexBox grown(int g) const { return {i0 - g, i1 + g, k0 - g, k1 + g}; }
  constexpr IndexBox intersect(const IndexBox& o) const {
    return {i0 > o.i0 ? i0 : o.i0, i1 < o.i1 ? i1 : o.i1, k0 > o.k0 ? k0 : o.k0,
            k1 < o.k1 ? k1 : o.k1};
  }
  constexpr bool operator==(const IndexBox& o) const {
    return i0 == o.i0 && i1 == o.i1 && k0 == o.k0 && k1 == o.k1;
  }
};

}  // namespace picdem::core

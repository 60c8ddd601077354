// Cut cells by intersecting each body boundary once with every grid line it spans (not with every
// cell edge). Everything is done in grid units, xi = (x - x0) / h, zeta = (z - z0) / h, where the
// grid lines are the integers. Decisions are exact: a segment end on a line is a comparison of
// doubles, a circle against a line is decided with CGAL's exact rationals when the double filter
// cannot tell. Every intersection point is computed once and used both for the face lengths and
// for the boundary pieces, which makes the discrete divergence theorem hold to round-off.
#include "picdem/geometry/cut_cells.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "picdem/core/error.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::geometry {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Q = CGAL::Exact_rational;

constexpr double kTwoPi = 2.0 * M_PI;

/// Sign of |j - c| - rho, exactly (j, c, rho as given doubles).
int compare_distance(double j, double c, double rho) {
  const double d = std::fabs(j - c) - rho;
  const double bound =
      8.0 * std::numeric_limits<double>::epsilon() * (std::fabs(j) + std::fabs(c) + rho);
  if (d > bound) return 1;
  if (d < -bound) return -1;
  // (j - c)^2 - rho^2, exactly.
  const Q dq = Q(j) - Q(c);
  const Q e = dq * dq - Q(rho) * Q(rho);
  return CGAL::sign(e);
}

/// zeta where the segment a-b meets the line xi = X (a.x and b.x on either side or on it).
double cross_at_x(Vec2 a, Vec2 b, double X) {
  if (a.x == X) return a.z;
  if (b.x == X) return b.z;
  if (b.x < a.x) std::swap(a, b);
  const double z = a.z + (X - a.x) / (b.x - a.x) * (b.z - a.z);
  return std::clamp(z, std::min(a.z, b.z), std::max(a.z, b.z));
}
double cross_at_z(Vec2 a, Vec2 b, double Z) {
  if (a.z == Z) return a.x;
  if (b.z == Z) return b.x;
  if (b.z < a.z) std::swap(a, b);
  const double x = a.x + (Z - a.z) / (b.z - a.z) * (b.x - a.x);
  return std::clamp(x, std::min(a.x, b.x), std::max(a.x, b.x));
}

/// A body boundary loop in grid units: a polygon (segments) or a full circle.
/// A boundary piece of a loop mixing segments and arcs, in grid units. a and b are the loop's
/// joints (shared bitwise with the neighbouring pieces).
struct UPiece {
  bool arc = false;
  Vec2 a, b;
  Vec2 c;
  double rho = 0.0, phi0 = 0.0, phi1 = 0.0;
};

struct Item {
  int tag = 0;  // solid index, or -1-k for obstacle k
  bool circle = false;
  std::vector<UPiece> loop;  // a loop with partial arcs (empty for polygons and circles)
  std::vector<Vec2> verts;   // polygon loop, CCW
  Vec2 c;                    // circle centre
  double rho = 0.0;
  Vec2 com;  // centre of mass (solids), grid units
  double lo_x = 0, hi_x = 0, lo_z = 0, hi_z = 0;
  std::function<bool(const Vec2&)> contains_world;
};

/// A grid line: vertical (xi = index) or horizontal (zeta = index); kind 0 = none.
struct Line {
  int kind = 0;
  int index = 0;
  bool operator==(const Line& o) const { return kind == o.kind && index == o.index; }
};
constexpr int kVertical = 1, kHorizontal = 2;

/// A piece of boundary inside one cell (grid units).
struct Sub {
  Vec2 p0, p1;
  bool arc = false;
  Vec2 c;             // arc centre
  double rho = 0.0;   // arc radius
  double phi0 = 0.0;  // arc start angle
  double dphi = 0.0;  // arc span
  int i = 0, k = 0;
  Line line0, line1;  // the grid lines the end points lie on (none for original end points)
};

struct Event {
  double t;  // parameter along the piece (segment t, arc angle)
  Vec2 p;
  Line line;
};

struct Interval {
  double lo, hi;
};

int floor_int(double v) {
  return static_cast<int>(std::floor(v));
}

bool is_integer(double v) {
  return v == std::floor(v);
}

/// The column (kind = kVertical; coordinates x) or row (kHorizontal; coordinates z) of a piece
/// whose midpoint coordinate is m. `on_line` says a segment keeps that coordinate constant, and
/// `normal_up` that its outward normal points to larger coordinates in that case.
int arc_or_segment_index(const Sub& s, double m, bool normal_up, double centre, double p0,
                         bool on_line, int kind) {
  if (!s.arc) {
    // A piece lying on a grid line belongs to the cell its outward normal points into.
    if (on_line && is_integer(p0))
      return normal_up ? static_cast<int>(p0) : static_cast<int>(p0) - 1;
    return floor_int(m);
  }
  const double j = std::round(m);
  if (std::fabs(m - j) > 1e-9) return floor_int(m);
  // The arc's midpoint is within round-off of line j: decide from the exact configuration.
  if (s.line0.kind == kind && s.line0 == s.line1 && s.line0.index == j) {
    // A short arc between two crossings of line j lies beyond the line, away from the centre.
    return centre < j ? static_cast<int>(j) : static_cast<int>(j) - 1;
  }
  if (compare_distance(j, centre, s.rho) >= 0) {
    // Touching (tangent) or missing the line: the arc is on the centre's side.
    return centre < j ? static_cast<int>(j) - 1 : static_cast<int>(j);
  }
  return floor_int(m);
}

/// Cell of a boundary piece that crosses no grid line in its interior.
void assign_cell(Sub& s) {
  const Vec2 d = s.p1 - s.p0;
  Vec2 m;
  if (!s.arc) {
    m = 0.5 * (s.p0 + s.p1);
  } else {
    const double am = s.phi0 + 0.5 * s.dphi;
    m = s.c + s.rho * Vec2{std::cos(am), std::sin(am)};
  }
  // Column, then row.
  s.i = arc_or_segment_index(s, m.x, d.z > 0, s.c.x, s.p0.x, d.x == 0.0, kVertical);
  s.k = arc_or_segment_index(s, m.z, d.x < 0, s.c.z, s.p0.z, d.z == 0.0, kHorizontal);
}

// The first moments of WettedPiece about the centre of cell (i, k), in world units, for a
// segment (p0 -> p1) or an arc (centre c, radius rho, from phi0 over dphi), all in window units
// (world = origin + h u); com is the body's centre of mass (window units), null for obstacles.
void set_moments(WettedPiece& p, const Sub& s, int i, int k, double h, const Vec2* com) {
  const Vec2 uc{i + 0.5, k + 0.5};
  const Vec2 d = s.p1 - s.p0, n_dl{d.z, -d.x};  // window units
  Vec2 mx, mz;                                    // int (u - uc)_x n dl_w, int (u - uc)_z n dl_w
  if (s.arc) {
    // u - uc = (c - uc) + rho n(phi), dl = rho dphi: int n n^T dphi in closed form
    const double a = s.phi0, b = s.phi0 + s.dphi;
    const double cc = 0.5 * s.dphi + 0.25 * (std::sin(2 * b) - std::sin(2 * a));
    const double ss = 0.5 * s.dphi - 0.25 * (std::sin(2 * b) - std::sin(2 * a));
    const double cs = 0.5 * (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a));
    const double r2 = s.rho * s.rho;
    const Vec2 e = s.c - uc;
    mx = Vec2{e.x * n_dl.x + r2 * cc, e.x * n_dl.z + r2 * cs};
    mz = Vec2{e.z * n_dl.x + r2 * cs, e.z * n_dl.z + r2 * ss};
  } else {
    const Vec2 m = 0.5 * (s.p0 + s.p1) - uc;  // n is constant: the midpoint rule is exact
    mx = m.x * n_dl;
    mz = m.z * n_dl;
  }
  p.dx_n_dl = h * h * mx;
  p.dz_n_dl = h * h * mz;
  p.d_r_cross_n_dl = Vec2{};
  if (!com) return;
  if (s.arc) {
    // r x n = (c - com) x n on an arc about c: linear in n
    const Vec2 l = s.c - *com;
    p.d_r_cross_n_dl = h * h * h * Vec2{l.x * mx.z - l.z * mx.x, l.x * mz.z - l.z * mz.x};
  } else {
    // (u - uc) and (u - com) x n_dl are linear along the segment: Simpson is exact
    auto t = [&](const Vec2& u) { return (u.x - com->x) * n_dl.z - (u.z - com->z) * n_dl.x; };
    const Vec2 a = s.p0 - uc, b = s.p1 - uc, m = 0.5 * (a + b);
    const Vec2 mid = 0.5 * (s.p0 + s.p1);
    const Vec2 sum = t(s.p0) * a + 4.0 * t(mid) * m + t(s.p1) * b;
    p.d_r_cross_n_dl = (h * h * h / 6.0) * sum;
  }
}

// 1/2 (x dz - z dx) integrated over the piece, relative to the centre of its cell.
double area_term(const Sub& s) {
  const Vec2 c{s.i + 0.5, s.k + 0.5};
  double a = 0.5 * core::cross(s.p0 - c, s.p1 - c);
  if (s.arc) {
    // circular segment between chord and arc: rho^2 / 2 (dphi - sin dphi)
    const double x = s.dphi;
    const double f =
        x < 1e-2 ? x * x * x / 6.0 * (1.0 - x * x / 20.0 * (1.0 - x * x / 42.0)) : x - std::sin(x);
    a += 0.5 * s.rho * s.rho * f;
  }
  return a;
}

/// Per-call working memory, reused from body to body.
struct Builder {
  GridWindow win;
  IndexBox W;  // window grown by one cell
  int nwx = 0, nwz = 0;
  std::vector<std::vector<Interval>> gx, gz;  // covered intervals on each line of W
  std::vector<double> covered;                // per cell: area terms of the visible boundary pieces
  std::vector<double> best_solid_area, best_obstacle_area;
  std::vector<int> best_solid, best_obstacle;
  std::vector<WettedPiece> pieces;

  // body scratch
  IndexBox B;
  std::vector<std::vector<Interval>> lx, lz;  // this body's intervals per line of B
  std::vector<std::vector<std::pair<double, int>>> ex_plus, ex_minus, ez_plus, ez_minus;
  std::vector<double> cx, cz, term;
  std::vector<unsigned char> touched;
  std::vector<Sub> subs;
  std::vector<Event> events;

  long long cell(int i, int k) const { return (i - W.i0) + static_cast<long long>(k - W.k0) * nwx; }
};

void merge(std::vector<Interval>& v) {
  if (v.size() < 2) return;
  std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  std::size_t n = 0;
  for (std::size_t j = 1; j < v.size(); ++j) {
    if (v[j].lo <= v[n].hi) {
      v[n].hi = std::max(v[n].hi, v[j].hi);
    } else {
      v[++n] = v[j];
    }
  }
  v.resize(n + 1);
}

/// Intervals where the winding number of the sorted (position, +1/-1) events is positive.
void sweep(std::vector<std::pair<double, int>>& ev, std::vector<Interval>& out) {
  std::sort(ev.begin(), ev.end());
  int w = 0;
  double start = 0.0;
  for (const auto& [z, d] : ev) {
    const int before = w;
    w += d;
    if (before <= 0 && w > 0) start = z;
    if (before > 0 && w <= 0 && z > start) out.push_back({start, z});
  }
}

/// Adds the covered length of merged intervals `v` on [lo_cell, hi_cell) faces into `c`.
void distribute(const std::vector<Interval>& v, int c0, int c1, double* c) {
  for (const auto& iv : v) {
    const int a = std::max(c0, floor_int(iv.lo)), b = std::min(c1 - 1, floor_int(iv.hi));
    for (int k = a; k <= b; ++k) {
      const double len = std::min(iv.hi, k + 1.0) - std::max(iv.lo, static_cast<double>(k));
      if (len > 0) c[k - c0] += len;
    }
  }
}

/// Splits the segment a-b at the grid lines and adds its crossings of the shifted lines.
void split_segment(const Vec2 a, const Vec2 b, Builder& bd) {
  {
    auto& ev = bd.events;
    ev.clear();
    ev.push_back({0.0, a, {}});
    if (a.x != b.x) {
      const int j0 = std::max(bd.W.i0, floor_int(std::min(a.x, b.x)) + 1);
      const int j1 = std::min(bd.W.i1, static_cast<int>(std::ceil(std::max(a.x, b.x))) - 1);
      for (int j = j0; j <= j1; ++j) {
        ev.push_back({(j - a.x) / (b.x - a.x), {double(j), cross_at_x(a, b, j)}, {kVertical, j}});
      }
    }
    if (a.z != b.z) {
      const int k0 = std::max(bd.W.k0, floor_int(std::min(a.z, b.z)) + 1);
      const int k1 = std::min(bd.W.k1, static_cast<int>(std::ceil(std::max(a.z, b.z))) - 1);
      for (int k = k0; k <= k1; ++k) {
        ev.push_back({(k - a.z) / (b.z - a.z), {cross_at_z(a, b, k), double(k)}, {kHorizontal, k}});
      }
    }
    std::sort(ev.begin() + 1, ev.end(), [](const Event& p, const Event& q) { return p.t < q.t; });
    ev.push_back({1.0, b, {}});
    for (std::size_t j = 0; j + 1 < ev.size(); ++j) {
      if (ev[j].p == ev[j + 1].p) continue;
      Sub s;
      s.p0 = ev[j].p;
      s.p1 = ev[j + 1].p;
      s.line0 = ev[j].line;
      s.line1 = ev[j + 1].line;
      assign_cell(s);
      bd.subs.push_back(s);
    }
    // Coverage events on the lines this edge reaches, for the lines shifted by -eps and +eps.
    const int dir_x = b.x > a.x ? 1 : -1;
    for (int j = std::max(bd.B.i0, static_cast<int>(std::ceil(std::min(a.x, b.x))));
         j <= std::min(bd.B.i1, floor_int(std::max(a.x, b.x))); ++j) {
      if ((a.x > j) != (b.x > j)) bd.ex_plus[j - bd.B.i0].push_back({cross_at_x(a, b, j), dir_x});
      if ((a.x >= j) != (b.x >= j))
        bd.ex_minus[j - bd.B.i0].push_back({cross_at_x(a, b, j), dir_x});
    }
    // Along a horizontal line the solid is on the left: travelling -zeta, it lies at +xi.
    const int dir_z = b.z > a.z ? -1 : 1;
    for (int k = std::max(bd.B.k0, static_cast<int>(std::ceil(std::min(a.z, b.z))));
         k <= std::min(bd.B.k1, floor_int(std::max(a.z, b.z))); ++k) {
      if ((a.z > k) != (b.z > k)) bd.ez_plus[k - bd.B.k0].push_back({cross_at_z(a, b, k), dir_z});
      if ((a.z >= k) != (b.z >= k))
        bd.ez_minus[k - bd.B.k0].push_back({cross_at_z(a, b, k), dir_z});
    }
  }
}

/// Splits an arc at the grid lines and adds its crossings of the lines shifted by +eps and -eps.
/// A crossing is decided exactly (compare_distance); whether a crossing lies inside the arc's
/// angle range is checked against the sides of the arc's end points (exact comparisons), which
/// settles the cases where a crossing and an end point coincide.
void split_arc(const UPiece& p, Builder& bd) {
  const double f0 = p.phi0, f1 = p.phi1;
  const double span = f1 - f0, delta = std::min(span, 1e-3);
  auto wrap = [f0](double a) {
    double t = std::fmod(a - f0, kTwoPi);
    if (t < 0) t += kTwoPi;
    return f0 + t;
  };
  auto gap = [](double a, double b) {
    const double t = std::fabs(std::fmod(a - b, kTwoPi));
    return std::min(t, kTwoPi - t);
  };
  auto& ev = bd.events;
  ev.clear();
  ev.push_back({f0, p.a, {}});
  struct Root {
    double ang, along;
    int dir;
    bool inside;
  };
  for (int axis = 0; axis < 2; ++axis) {
    const bool vert = axis == 0;
    const double cc = vert ? p.c.x : p.c.z, ca = vert ? p.c.z : p.c.x;
    const double a_c = vert ? p.a.x : p.a.z, b_c = vert ? p.b.x : p.b.z;
    const double a_l = vert ? p.a.z : p.a.x, b_l = vert ? p.b.z : p.b.x;
    const int lo = vert ? bd.B.i0 : bd.B.k0, hi = vert ? bd.B.i1 : bd.B.k1;
    auto& plus = vert ? bd.ex_plus : bd.ez_plus;
    auto& minus = vert ? bd.ex_minus : bd.ez_minus;
    // Motion across the lines just after the start (start = true) or just before the end: > 0
    // when the coordinate across the lines grows. The sweep counts +1 for a crossing of a
    // vertical line towards +xi and of a horizontal line towards -zeta.
    auto grow = [&](bool start) {
      const double mid = start ? f0 + 0.5 * delta : f1 - 0.5 * delta;
      return vert ? -std::sin(mid) : std::cos(mid);
    };
    auto dir_of = [vert](double g) { return (g > 0) == vert ? 1 : -1; };
    for (int j = std::max(lo, floor_int(cc - p.rho)); j <= std::min(hi, floor_int(cc + p.rho) + 1);
         ++j) {
      Root r[2];
      int nr = 0;
      if (compare_distance(j, cc, p.rho) < 0) {
        const double d = j - cc;
        const double s = std::sqrt(std::max(0.0, (p.rho - d) * (p.rho + d)));
        if (vert) {
          r[0] = {wrap(std::atan2(-s, d)), ca - s, 1, false};
          r[1] = {wrap(std::atan2(s, d)), ca + s, -1, false};
        } else {
          r[0] = {wrap(std::atan2(d, -s)), ca - s, 1, false};
          r[1] = {wrap(std::atan2(d, s)), ca + s, -1, false};
        }
        nr = 2;
        for (auto& q : r) {
          // A crossing at an end point lying exactly on the line is handled by that end point.
          const bool at_end =
              (a_c == j && gap(q.ang, f0) < 1e-6) || (b_c == j && gap(q.ang, f1) < 1e-6);
          q.inside = !at_end && q.ang > f0 && q.ang < f1;
        }
      }
      const Line line{vert ? kVertical : kHorizontal, j};
      for (int q = 0; q < nr; ++q) {
        if (!r[q].inside) continue;
        ev.push_back(
            {r[q].ang, vert ? Vec2{double(j), r[q].along} : Vec2{r[q].along, double(j)}, line});
      }
      for (int e = 0; e < 2; ++e) {
        // e = 0: the line shifted by +eps (points on it count as below); e = 1: by -eps.
        const bool sa = e == 0 ? a_c > j : a_c >= j, sb = e == 0 ? b_c > j : b_c >= j;
        auto& out = (e == 0 ? plus : minus)[j - lo];
        int crossings = 0;
        if (a_c == j) {
          const double g = grow(true);
          if ((e == 0) == (g > 0)) out.push_back({a_l, dir_of(g)}), ++crossings;
        }
        if (b_c == j) {
          const double g = grow(false);
          if ((e == 0) == (g < 0)) out.push_back({b_l, dir_of(g)}), ++crossings;
        }
        bool inc[2] = {nr > 0 && r[0].inside, nr > 0 && r[1].inside};
        crossings += (inc[0] ? 1 : 0) + (inc[1] ? 1 : 0);
        if ((crossings % 2 == 1) != (sa != sb)) {
          // A crossing within round-off of an end point that is not on the line: trust the end
          // points' sides (exact) and flip the crossing nearest to an end.
          int best = -1;
          double best_gap = 1e-6;
          for (int q = 0; q < nr; ++q) {
            const double g = std::min(gap(r[q].ang, f0), gap(r[q].ang, f1));
            if (g < best_gap) best_gap = g, best = q;
          }
          if (best >= 0) inc[best] = !inc[best];
        }
        for (int q = 0; q < nr; ++q) {
          if (inc[q]) out.push_back({r[q].along, r[q].dir});
        }
      }
    }
  }
  std::sort(ev.begin() + 1, ev.end(), [](const Event& x, const Event& y) { return x.t < y.t; });
  ev.push_back({f1, p.b, {}});
  for (std::size_t j = 0; j + 1 < ev.size(); ++j) {
    const double dphi = ev[j + 1].t - ev[j].t;
    if (dphi <= 0.0 || (ev[j].p == ev[j + 1].p && dphi < M_PI)) continue;
    Sub s;
    s.arc = true;
    s.c = p.c;
    s.rho = p.rho;
    s.phi0 = ev[j].t;
    s.dphi = dphi;
    s.p0 = ev[j].p;
    s.p1 = ev[j + 1].p;
    s.line0 = ev[j].line;
    s.line1 = ev[j + 1].line;
    assign_cell(s);
    bd.subs.push_back(s);
  }
}

/// Turns the crossings of the shifted lines into covered intervals per line.
void finish_coverage(Builder& bd) {
  for (int j = bd.B.i0; j <= bd.B.i1; ++j) {
    auto& v = bd.lx[j - bd.B.i0];
    sweep(bd.ex_plus[j - bd.B.i0], v);
    sweep(bd.ex_minus[j - bd.B.i0], v);
    merge(v);
  }
  for (int k = bd.B.k0; k <= bd.B.k1; ++k) {
    auto& v = bd.lz[k - bd.B.k0];
    sweep(bd.ez_plus[k - bd.B.k0], v);
    sweep(bd.ez_minus[k - bd.B.k0], v);
    merge(v);
  }
}

void split_polygon(const Item& it, Builder& bd) {
  const std::size_t n = it.verts.size();
  for (std::size_t e = 0; e < n; ++e) split_segment(it.verts[e], it.verts[(e + 1) % n], bd);
  finish_coverage(bd);
}

void split_loop(const Item& it, Builder& bd) {
  for (const auto& p : it.loop) {
    if (p.arc) {
      split_arc(p, bd);
    } else {
      split_segment(p.a, p.b, bd);
    }
  }
  finish_coverage(bd);
}

void split_circle(const Item& it, Builder& bd) {
  auto& ev = bd.events;
  ev.clear();
  const Vec2 c = it.c;
  const double rho = it.rho;
  for (int j = std::max(bd.B.i0, floor_int(c.x - rho));
       j <= std::min(bd.B.i1, floor_int(c.x + rho) + 1); ++j) {
    if (compare_distance(j, c.x, rho) >= 0) continue;
    const double d = j - c.x;
    // s = sqrt(rho^2 - d^2)
    const double s = std::sqrt(std::max(0.0, (rho - d) * (rho + d)));
    bd.lx[j - bd.B.i0].push_back({c.z - s, c.z + s});
    if (j < bd.W.i0 || j > bd.W.i1) continue;
    double lo = std::atan2(-s, d), hi = std::atan2(s, d);
    if (lo < 0) lo += kTwoPi;
    if (hi < 0) hi += kTwoPi;
    ev.push_back({lo, {double(j), c.z - s}, {kVertical, j}});
    ev.push_back({hi, {double(j), c.z + s}, {kVertical, j}});
  }
  for (int k = std::max(bd.B.k0, floor_int(c.z - rho));
       k <= std::min(bd.B.k1, floor_int(c.z + rho) + 1); ++k) {
    if (compare_distance(k, c.z, rho) >= 0) continue;
    const double d = k - c.z;
    const double s = std::sqrt(std::max(0.0, (rho - d) * (rho + d)));
    bd.lz[k - bd.B.k0].push_back({c.x - s, c.x + s});
    if (k < bd.W.k0 || k > bd.W.k1) continue;
    double left = std::atan2(d, -s), right = std::atan2(d, s);
    if (left < 0) left += kTwoPi;
    if (right < 0) right += kTwoPi;
    ev.push_back({right, {c.x + s, double(k)}, {kHorizontal, k}});
    ev.push_back({left, {c.x - s, double(k)}, {kHorizontal, k}});
  }
  if (ev.empty()) {
    Sub s;
    s.arc = true;
    s.c = c;
    s.rho = rho;
    s.p0 = s.p1 = c + Vec2{rho, 0.0};
    s.dphi = kTwoPi;
    s.i = floor_int(c.x);
    s.k = floor_int(c.z);
    bd.subs.push_back(s);
    return;
  }
  std::sort(ev.begin(), ev.end(), [](const Event& p, const Event& q) { return p.t < q.t; });
  for (std::size_t j = 0; j < ev.size(); ++j) {
    const Event& e0 = ev[j];
    const Event& e1 = ev[(j + 1) % ev.size()];
    double dphi = e1.t - e0.t;
    if (j + 1 == ev.size()) dphi += kTwoPi;
    if (dphi <= 0.0 || (e0.p == e1.p && dphi < M_PI)) continue;
    Sub s;
    s.arc = true;
    s.c = c;
    s.rho = rho;
    s.phi0 = e0.t;
    s.p0 = e0.p;
    s.p1 = e1.p;
    s.dphi = dphi;
    s.line0 = e0.line;
    s.line1 = e1.line;
    assign_cell(s);
    bd.subs.push_back(s);
  }
}

void add_item(const Item& it, const std::vector<Item>& items, const std::vector<int>& neighbours,
              Builder& bd) {
  // Cells that this item can touch: its bounding box plus one cell (pieces lying on a line
  // belong to the cell outside), clipped to the grown window.
  bd.B = IndexBox{floor_int(it.lo_x) - 1, floor_int(it.hi_x) + 2, floor_int(it.lo_z) - 1,
                  floor_int(it.hi_z) + 2}
             .intersect(bd.W);
  if (bd.B.empty()) return;
  const int bnx = bd.B.nx(), bnz = bd.B.nz();
  auto reset = [](auto& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
    for (std::size_t j = 0; j < n; ++j) v[j].clear();
  };
  reset(bd.lx, bnx + 1);
  reset(bd.lz, bnz + 1);
  reset(bd.ex_plus, bnx + 1);
  reset(bd.ex_minus, bnx + 1);
  reset(bd.ez_plus, bnz + 1);
  reset(bd.ez_minus, bnz + 1);
  bd.subs.clear();
  if (it.circle) {
    split_circle(it, bd);
  } else if (!it.loop.empty()) {
    split_loop(it, bd);
  } else {
    split_polygon(it, bd);
  }
  // Per-face covered lengths of this item over B.
  bd.cx.assign(static_cast<std::size_t>(bnx + 1) * bnz, 0.0);
  bd.cz.assign(static_cast<std::size_t>(bnx) * (bnz + 1), 0.0);
  for (int j = 0; j <= bnx; ++j) {
    merge(bd.lx[j]);
    std::vector<double> col(bnz, 0.0);
    distribute(bd.lx[j], bd.B.k0, bd.B.k1, col.data());
    for (int k = 0; k < bnz; ++k) bd.cx[j + static_cast<std::size_t>(k) * (bnx + 1)] = col[k];
    auto& g = bd.gx[bd.B.i0 + j - bd.W.i0];
    g.insert(g.end(), bd.lx[j].begin(), bd.lx[j].end());
  }
  for (int k = 0; k <= bnz; ++k) {
    merge(bd.lz[k]);
    distribute(bd.lz[k], bd.B.i0, bd.B.i1, &bd.cz[static_cast<std::size_t>(k) * bnx]);
    auto& g = bd.gz[bd.B.k0 + k - bd.W.k0];
    g.insert(g.end(), bd.lz[k].begin(), bd.lz[k].end());
  }
  // Boundary pieces: drop those inside another body (union), add area terms, chain by cell.
  bd.term.assign(static_cast<std::size_t>(bnx) * bnz, 0.0);
  bd.touched.assign(static_cast<std::size_t>(bnx) * bnz, 0);
  const GridWindow& w = bd.win;
  auto world = [&w](const Vec2& u) { return w.origin + w.h * u; };
  std::vector<WettedPiece> chain;
  for (const Sub& s : bd.subs) {
    if (!bd.B.contains(s.i, s.k)) continue;
    bool hidden = false;
    if (!neighbours.empty()) {
      // The piece's midpoint (on the arc for arcs) inside or on another body hides the piece.
      Vec2 m = 0.5 * (s.p0 + s.p1);
      if (s.arc) {
        const double am = s.phi0 + 0.5 * s.dphi;
        m = s.c + s.rho * Vec2{std::cos(am), std::sin(am)};
      }
      for (int o : neighbours) {
        const Item& other = items[o];
        if (m.x < other.lo_x || m.x > other.hi_x || m.z < other.lo_z || m.z > other.hi_z) continue;
        if (other.contains_world(world(m))) {
          hidden = true;
          break;
        }
      }
    }
    if (hidden) continue;
    const std::size_t c = (s.i - bd.B.i0) + static_cast<std::size_t>(s.k - bd.B.k0) * bnx;
    const double a_piece = area_term(s);
    bd.term[c] += a_piece;
    bd.covered[bd.cell(s.i, s.k)] += a_piece;
    bd.touched[c] = 1;
    const Vec2 d = s.p1 - s.p0;
    WettedPiece p;
    p.body = it.tag;
    p.i = s.i;
    p.k = s.k;
    p.p0 = world(s.p0);
    p.p1 = world(s.p1);
    // integral of n dl = (d zeta, -d xi) h for any curve with the body on its left
    p.n_dl = w.h * Vec2{d.z, -d.x};
    if (it.tag >= 0) {
      // (r x n) dl = -d(|r|^2 / 2): -(p1 - p0) . ((p0 + p1) / 2 - X); on an arc about c,
      // -(p1 - p0) . (c - X)
      const Vec2 lever = s.arc ? s.c - it.com : 0.5 * (s.p0 + s.p1) - it.com;
      p.r_cross_n_dl = -w.h * w.h * core::dot(d, lever);
    }
    set_moments(p, s, s.i, s.k, w.h, it.tag >= 0 ? &it.com : nullptr);
    p.length = w.h * (s.arc ? s.rho * s.dphi : core::norm(d));
    if (!chain.empty() && chain.back().i == p.i && chain.back().k == p.k &&
        chain.back().p1 == p.p0) {
      auto& q = chain.back();
      q.p1 = p.p1;
      q.n_dl += p.n_dl;
      q.r_cross_n_dl += p.r_cross_n_dl;
      q.dx_n_dl += p.dx_n_dl;
      q.dz_n_dl += p.dz_n_dl;
      q.d_r_cross_n_dl += p.d_r_cross_n_dl;
      q.length += p.length;
    } else {
      chain.push_back(p);
    }
  }
  // The loop is closed: its last run joins the first when they share a cell.
  if (chain.size() > 1 && chain.back().i == chain.front().i && chain.back().k == chain.front().k &&
      chain.back().p1 == chain.front().p0) {
    auto& q = chain.front();
    q.p0 = chain.back().p0;
    q.n_dl += chain.back().n_dl;
    q.r_cross_n_dl += chain.back().r_cross_n_dl;
    q.dx_n_dl += chain.back().dx_n_dl;
    q.dz_n_dl += chain.back().dz_n_dl;
    q.d_r_cross_n_dl += chain.back().d_r_cross_n_dl;
    q.length += chain.back().length;
    chain.pop_back();
  }
  bd.pieces.insert(bd.pieces.end(), chain.begin(), chain.end());
  // Covered area per cell: (1/4) sum of covered face lengths + sum of 1/2 (x dz - z dx).
  for (int k = 0; k < bnz; ++k) {
    for (int i = 0; i < bnx; ++i) {
      const std::size_t c = i + static_cast<std::size_t>(k) * bnx;
      const double faces = bd.cx[i + static_cast<std::size_t>(k) * (bnx + 1)] +
                           bd.cx[i + 1 + static_cast<std::size_t>(k) * (bnx + 1)] +
                           bd.cz[i + static_cast<std::size_t>(k) * bnx] +
                           bd.cz[i + static_cast<std::size_t>(k + 1) * bnx];
      if (faces == 0.0 && !bd.touched[c]) continue;
      const double area = std::clamp(0.25 * faces + bd.term[c], 0.0, 1.0);
      const long long g = bd.cell(bd.B.i0 + i, bd.B.k0 + k);
      if (it.tag >= 0) {
        if (area > bd.best_solid_area[g]) {
          bd.best_solid_area[g] = area;
          bd.best_solid[g] = it.tag;
        }
      } else if (area > bd.best_obstacle_area[g]) {
        bd.best_obstacle_area[g] = area;
        bd.best_obstacle[g] = -1 - it.tag;
      }
    }
  }
}

Item make_polygon_item(int tag, const std::vector<Vec2>& world_verts, const GridWindow& w) {
  Item it;
  it.tag = tag;
  it.lo_x = it.lo_z = INFINITY;
  it.hi_x = it.hi_z = -INFINITY;
  for (const auto& p : world_verts) {
    const Vec2 u = (p - w.origin) / w.h;
    it.verts.push_back(u);
    it.lo_x = std::min(it.lo_x, u.x);
    it.hi_x = std::max(it.hi_x, u.x);
    it.lo_z = std::min(it.lo_z, u.z);
    it.hi_z = std::max(it.hi_z, u.z);
  }
  return it;
}

}  // namespace

CutCells build_cut_cells(const GridWindow& window, const std::vector<SolidPlacement>& solids,
                         const std::vector<Obstacle>& obstacles, const CutCellOptions& options) {
  if (!(window.h > 0.0)) {
    std::ostringstream m;
    m << "cut cells: grid cell size h = " << window.h << " is not allowed: it must be > 0";
    throw core::InputError(m.str());
  }
  Builder bd;
  bd.win = window;
  bd.W = window.cells.grown(1);
  bd.nwx = bd.W.nx();
  bd.nwz = bd.W.nz();
  const std::size_t ncell = static_cast<std::size_t>(bd.nwx) * bd.nwz;
  bd.gx.resize(bd.nwx + 1);
  bd.gz.resize(bd.nwz + 1);
  bd.covered.assign(ncell, 0.0);
  bd.best_solid_area.assign(ncell, -1.0);
  bd.best_obstacle_area.assign(ncell, -1.0);
  bd.best_solid.assign(ncell, -1);
  bd.best_obstacle.assign(ncell, -1);

  // Items in grid units.
  std::vector<Item> items;
  const core::Box2 wbox{window.origin + window.h * Vec2{double(bd.W.i0), double(bd.W.k0)},
                        window.origin + window.h * Vec2{double(bd.W.i1), double(bd.W.k1)}};
  for (std::size_t s = 0; s < solids.size(); ++s) {
    const auto& sp = solids[s];
    if (!sp.shape)
      throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " has no shape");
    const double R = sp.shape->bounding_radius();
    if (sp.pose.x.x + R < wbox.lo.x || sp.pose.x.x - R > wbox.hi.x || sp.pose.x.z + R < wbox.lo.z ||
        sp.pose.x.z - R > wbox.hi.z) {
      continue;
    }
    const Vec2 com = (sp.pose.x - window.origin) / window.h;
    const std::vector<BoundaryPiece> boundary = sp.shape->boundary();
    if (boundary.empty()) {
      throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " of kind '" +
                             sp.shape->kind() + "' has an empty boundary");
    }
    auto to_unit = [&](const Vec2& body) {
      return (sp.pose.to_world(body) - window.origin) / window.h;
    };
    const auto* first_arc = std::get_if<Arc>(&boundary[0]);
    bool all_segments = true;
    for (const auto& piece : boundary)
      all_segments = all_segments && std::holds_alternative<Segment>(piece);
    if (boundary.size() == 1 && first_arc && first_arc->phi1 - first_arc->phi0 >= kTwoPi) {
      // A full circle.
      Item it;
      it.tag = static_cast<int>(s);
      it.circle = true;
      it.c = to_unit(first_arc->centre);
      it.rho = first_arc->radius / window.h;
      it.lo_x = it.c.x - it.rho;
      it.hi_x = it.c.x + it.rho;
      it.lo_z = it.c.z - it.rho;
      it.hi_z = it.c.z + it.rho;
      it.com = com;
      items.push_back(it);
    } else if (all_segments) {
      std::vector<Vec2> verts;
      for (const auto& piece : boundary)
        verts.push_back(sp.pose.to_world(std::get<Segment>(piece).a));
      Item it = make_polygon_item(static_cast<int>(s), verts, window);
      it.com = com;
      items.push_back(std::move(it));
    } else {
      // Segments and arcs: joints shared bitwise between neighbouring pieces.
      Item it;
      it.tag = static_cast<int>(s);
      it.com = com;
      const std::size_t n = boundary.size();
      it.loop.resize(n);
      for (std::size_t j = 0; j < n; ++j) {
        UPiece& u = it.loop[j];
        if (const auto* seg = std::get_if<Segment>(&boundary[j])) {
          u.a = to_unit(seg->a);
        } else {
          const auto& arc = std::get<Arc>(boundary[j]);
          if (!(arc.radius > 0.0) || !(arc.phi1 > arc.phi0) || arc.phi1 - arc.phi0 > kTwoPi) {
            throw core::InputError("cut cells: solid " + std::to_string(sp.id) + " of kind '" +
                                   sp.shape->kind() +
                                   "' has an arc with radius <= 0 or a span outside (0, 2 pi]");
          }
          u.arc = true;
          u.c = to_unit(arc.centre);
          u.rho = arc.radius / window.h;
          u.phi0 = arc.phi0 + sp.pose.theta;
          u.phi1 = arc.phi1 + sp.pose.theta;
          const auto* prev = std::get_if<Segment>(&boundary[(j + n - 1) % n]);
          u.a = prev ? to_unit(prev->b) : u.c + u.rho * Vec2{std::cos(u.phi0), std::sin(u.phi0)};
        }
      }
      it.lo_x = it.lo_z = INFINITY;
      it.hi_x = it.hi_z = -INFINITY;
      for (std::size_t j = 0; j < n; ++j) {
        UPiece& u = it.loop[j];
        u.b = it.loop[(j + 1) % n].a;
        const Vec2 lo =
            u.arc ? u.c - Vec2{u.rho, u.rho} : Vec2{std::min(u.a.x, u.b.x), std::min(u.a.z, u.b.z)};
        const Vec2 hi =
            u.arc ? u.c + Vec2{u.rho, u.rho} : Vec2{std::max(u.a.x, u.b.x), std::max(u.a.z, u.b.z)};
        it.lo_x = std::min(it.lo_x, lo.x);
        it.lo_z = std::min(it.lo_z, lo.z);
        it.hi_x = std::max(it.hi_x, hi.x);
        it.hi_z = std::max(it.hi_z, hi.z);
      }
      items.push_back(std::move(it));
    }
    const ShapePtr shape = sp.shape;
    const Pose pose = sp.pose;
    items.back().contains_world = [shape, pose](const Vec2& p) {
      return shape->contains(pose.to_body(p));
    };
  }
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    for (const auto& poly : obstacles[o].polygons) {
      Item it = make_polygon_item(-1 - static_cast<int>(o), poly, window);
      if (it.hi_x < bd.W.i0 - 1 || it.lo_x > bd.W.i1 + 1 || it.hi_z < bd.W.k0 - 1 ||
          it.lo_z > bd.W.k1 + 1) {
        continue;
      }
      std::vector<K::Point_2> pts;
      for (const auto& p : poly) pts.emplace_back(p.x, p.z);
      it.contains_world = [pts](const Vec2& p) {
        return CGAL::bounded_side_2(pts.begin(), pts.end(), K::Point_2(p.x, p.z), K()) !=
               CGAL::ON_UNBOUNDED_SIDE;
      };
      items.push_back(std::move(it));
    }
  }
  // Items whose boxes overlap (candidates for hiding each other's boundary).
  std::vector<std::vector<int>> neighbours(items.size());
  {
    std::vector<int> order(items.size());
    for (std::size_t j = 0; j < items.size(); ++j) order[j] = static_cast<int>(j);
    std::sort(order.begin(), order.end(),
              [&items](int a, int b) { return items[a].lo_x < items[b].lo_x; });
    for (std::size_t a = 0; a < order.size(); ++a) {
      const Item& p = items[order[a]];
      for (std::size_t b = a + 1; b < order.size() && items[order[b]].lo_x <= p.hi_x; ++b) {
        const Item& q = items[order[b]];
        if (q.lo_z <= p.hi_z && p.lo_z <= q.hi_z) {
          neighbours[order[a]].push_back(order[b]);
          neighbours[order[b]].push_back(order[a]);
        }
      }
    }
    for (auto& nb : neighbours) std::sort(nb.begin(), nb.end());
  }
  for (std::size_t j = 0; j < items.size(); ++j) add_item(items[j], items, neighbours[j], bd);
  std::vector<int> item_of_solid(solids.size(), 0);
  for (std::size_t j = 0; j < items.size(); ++j) {
    if (items[j].tag >= 0) item_of_solid[items[j].tag] = static_cast<int>(j);
  }

  // E_f = h - (covered length of face f), the union over all bodies (the E of eq. 5).
  CutCells cc;
  cc.window = window;
  cc.store = bd.W;
  cc.ex.assign(static_cast<std::size_t>(bd.nwx + 1) * bd.nwz, 1.0);
  cc.ez.assign(static_cast<std::size_t>(bd.nwx) * (bd.nwz + 1), 1.0);
  std::vector<double> col(bd.nwz);
  for (int j = 0; j <= bd.nwx; ++j) {
    auto& v = bd.gx[j];
    if (v.empty()) continue;
    merge(v);
    std::fill(col.begin(), col.end(), 0.0);
    distribute(v, bd.W.k0, bd.W.k1, col.data());
    for (int k = 0; k < bd.nwz; ++k)
      cc.ex[j + static_cast<std::size_t>(k) * (bd.nwx + 1)] -= col[k];
  }
  std::vector<double> row(bd.nwx);
  for (int k = 0; k <= bd.nwz; ++k) {
    auto& v = bd.gz[k];
    if (v.empty()) continue;
    merge(v);
    std::fill(row.begin(), row.end(), 0.0);
    distribute(v, bd.W.i0, bd.W.i1, row.data());
    for (int i = 0; i < bd.nwx; ++i) cc.ez[i + static_cast<std::size_t>(k) * bd.nwx] -= row[i];
  }
  for (auto& e : cc.ex) e = std::max(0.0, e);
  for (auto& e : cc.ez) e = std::max(0.0, e);
  // Covered area of the union: 1/4 (sum of covered face lengths) + the visible pieces' terms.
  cc.fraction = std::move(bd.covered);
  for (int k = 0; k < bd.nwz; ++k) {
    for (int i = 0; i < bd.nwx; ++i) {
      const std::size_t c = i + static_cast<std::size_t>(k) * bd.nwx;
      const std::size_t fx = i + static_cast<std::size_t>(k) * (bd.nwx + 1);
      const double open = cc.ex[fx] + cc.ex[fx + 1] + cc.ez[c] + cc.ez[c + bd.nwx];
      if (open == 4.0 && cc.fraction[c] == 0.0) {
        cc.fraction[c] = 1.0;
        continue;
      }
      const double covered = 0.25 * (4.0 - open) + cc.fraction[c];
      cc.fraction[c] = 1.0 - std::clamp(covered, 0.0, 1.0);
    }
  }
  cc.body = bd.best_solid;  // copied: the tiny-cell rule below still reads the best areas
  cc.obstacle = std::move(bd.best_obstacle);
  cc.tiny.assign(ncell, 0);

  // Tiny cells: fraction below the threshold and still open somewhere -> dropped.
  auto exi = [&](int i, int k) -> double& {
    return cc.ex[(i - bd.W.i0) + static_cast<std::size_t>(k - bd.W.k0) * (bd.nwx + 1)];
  };
  auto ezi = [&](int i, int k) -> double& {
    return cc.ez[(i - bd.W.i0) + static_cast<std::size_t>(k - bd.W.k0) * bd.nwx];
  };
  for (int k = bd.W.k0; k < bd.W.k1; ++k) {
    for (int i = bd.W.i0; i < bd.W.i1; ++i) {
      const long long c = bd.cell(i, k);
      if (cc.fraction[c] < options.tiny_fraction &&
          (exi(i, k) > 0 || exi(i + 1, k) > 0 || ezi(i, k) > 0 || ezi(i, k + 1) > 0)) {
        cc.tiny[c] = 1;
      }
    }
  }
  std::vector<WettedPiece> closing;
  auto open_parts = [](const std::vector<Interval>& covered, double a, double b) {
    std::vector<Interval> open;
    double at = a;
    for (const auto& iv : covered) {
      if (iv.hi <= at || iv.lo >= b) continue;
      if (iv.lo > at) open.push_back({at, iv.lo});
      at = std::max(at, iv.hi);
    }
    if (at < b) open.push_back({at, b});
    return open;
  };
  for (int k = bd.W.k0; k < bd.W.k1; ++k) {
    for (int i = bd.W.i0; i < bd.W.i1; ++i) {
      const long long c = bd.cell(i, k);
      if (!cc.tiny[c]) continue;
      const bool solid_owner =
          bd.best_solid_area[c] >= bd.best_obstacle_area[c] && bd.best_solid[c] >= 0;
      const int tag = solid_owner ? bd.best_solid[c] : -1 - cc.obstacle[c];
      const Item* owner = tag >= 0 ? &items[item_of_solid[tag]] : nullptr;
      // Faces: (neighbour i, k, vertical?, line index, dropped cell on the low side?)
      struct F {
        int ni, nk;
        bool vertical;
        int line;
        bool low;
      };
      const F faces[4] = {{i - 1, k, true, i, false},
                          {i + 1, k, true, i + 1, true},
                          {i, k - 1, false, k, false},
                          {i, k + 1, false, k + 1, true}};
      for (const F& f : faces) {
        double& E = f.vertical ? exi(f.line, k) : ezi(i, f.line);
        if (E <= 0 || !bd.W.contains(f.ni, f.nk) || cc.tiny[bd.cell(f.ni, f.nk)]) continue;
        const auto& cov = f.vertical ? bd.gx[f.line - bd.W.i0] : bd.gz[f.line - bd.W.k0];
        const double a = f.vertical ? k : i;
        for (const auto& iv : open_parts(cov, a, a + 1.0)) {
          // Outward normal of the enlarged body points into the neighbour.
          Vec2 p0, p1;
          if (f.vertical) {
            p0 = {double(f.line), f.low ? iv.lo : iv.hi};
            p1 = {double(f.line), f.low ? iv.hi : iv.lo};
          } else {
            p0 = {f.low ? iv.hi : iv.lo, double(f.line)};
            p1 = {f.low ? iv.lo : iv.hi, double(f.line)};
          }
          const Vec2 d = p1 - p0;
          WettedPiece p;
          p.body = tag;
          p.i = f.ni;
          p.k = f.nk;
          p.p0 = window.origin + window.h * p0;
          p.p1 = window.origin + window.h * p1;
          p.n_dl = window.h * Vec2{d.z, -d.x};
          if (tag >= 0 && owner) {
            p.r_cross_n_dl = -window.h * window.h * core::dot(d, 0.5 * (p0 + p1) - owner->com);
          }
          Sub segment;
          segment.p0 = p0, segment.p1 = p1;
          set_moments(p, segment, f.ni, f.nk, window.h, tag >= 0 && owner ? &owner->com : nullptr);
          p.length = window.h * core::norm(d);
          p.closes_tiny_cell = true;
          closing.push_back(p);
          if (tag >= 0 && cc.body[bd.cell(f.ni, f.nk)] < 0) cc.body[bd.cell(f.ni, f.nk)] = tag;
        }
      }
    }
  }
  for (int k = bd.W.k0; k < bd.W.k1; ++k) {
    for (int i = bd.W.i0; i < bd.W.i1; ++i) {
      const long long c = bd.cell(i, k);
      if (!cc.tiny[c]) continue;
      exi(i, k) = exi(i + 1, k) = ezi(i, k) = ezi(i, k + 1) = 0.0;
      cc.fraction[c] = 0.0;
    }
  }
  bd.pieces.insert(bd.pieces.end(), closing.begin(), closing.end());
  // Keep the window's pieces outside dropped cells, in cell order, then body order.
  for (const auto& p : bd.pieces) {
    if (window.cells.contains(p.i, p.k) && !cc.tiny[bd.cell(p.i, p.k)]) cc.pieces.push_back(p);
  }
  std::stable_sort(cc.pieces.begin(), cc.pieces.end(),
                   [](const WettedPiece& a, const WettedPiece& b) {
                     if (a.k != b.k) return a.k < b.k;
                     if (a.i != b.i) return a.i < b.i;
                     if (a.body != b.body)
                       return (a.body >= 0 ? a.body : 1000000000 - a.body) <
                              (b.body >= 0 ? b.body : 1000000000 - b.body);
                     return a.closes_tiny_cell < b.closes_tiny_cell;
                   });
  return cc;
}

namespace {
[[noreturn]] void out_of_window(const char* what, int i, int k, const IndexBox& b) {
  std::ostringstream m;
  m << "CutCells::" << what << "(" << i << ", " << k << ") is outside the window [" << b.i0 << ", "
    << b.i1 << ") x [" << b.k0 << ", " << b.k1 << ")";
  throw std::out_of_range(m.str());
}
}  // namespace

double CutCells::E_x(int i, int k) const {
  const auto& b = window.cells;
  if (i < b.i0 || i > b.i1 || k < b.k0 || k >= b.k1) out_of_window("E_x", i, k, b);
  return window.h * ex[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * (store.nx() + 1)];
}
double CutCells::E_z(int i, int k) const {
  const auto& b = window.cells;
  if (i < b.i0 || i >= b.i1 || k < b.k0 || k > b.k1) out_of_window("E_z", i, k, b);
  return window.h * ez[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
double CutCells::fluid_fraction(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("fluid_fraction", i, k, window.cells);
  return fraction[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
int CutCells::cutting_body(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("cutting_body", i, k, window.cells);
  return body[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
int CutCells::cutting_obstacle(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("cutting_obstacle", i, k, window.cells);
  return obstacle[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()];
}
bool CutCells::dropped(int i, int k) const {
  if (!window.cells.contains(i, k)) out_of_window("dropped", i, k, window.cells);
  return tiny[(i - store.i0) + static_cast<std::size_t>(k - store.k0) * store.nx()] != 0;
}

}  // namespace picdem::geometry

// Clipping: a body's boundary split at the grid lines it crosses, each line intersected once per
// boundary piece, into pieces that each lie in one cell (Sub), and the same crossings recorded on
// the lines shifted by +eps and -eps for the lines' covered intervals (cut_cells_apertures.cpp).
// Decisions are exact: a segment end on a line is a comparison of doubles, a circle against a line
// is decided with CGAL's exact rationals when the double filter cannot tell.
#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cut_cells_internal.hpp"

namespace picdem::geometry::detail {

namespace {

using Q = CGAL::Exact_rational;

/// Where the segment a-b meets the grid line xi = X (kVertical: returns zeta) or zeta = X
/// (kHorizontal: returns xi), a and b on either side of the line or on it.
template <int kind>
double cross_at(Vec2 a, Vec2 b, double X) {
  auto across = [](const Vec2& p) { return kind == kVertical ? p.x : p.z; };
  auto along = [](const Vec2& p) { return kind == kVertical ? p.z : p.x; };
  if (across(a) == X) return along(a);
  if (across(b) == X) return along(b);
  if (across(b) < across(a)) std::swap(a, b);
  const double t = along(a) + (X - across(a)) / (across(b) - across(a)) * (along(b) - along(a));
  return std::clamp(t, std::min(along(a), along(b)), std::max(along(a), along(b)));
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

/// The piece of boundary from event e0 to event e1, in its cell; `s` carries an arc's centre,
/// radius and angles (a default Sub for a segment).
void push_sub(Sub s, const Event& e0, const Event& e1, Builder& bd) {
  s.p0 = e0.p;
  s.p1 = e1.p;
  s.line0 = e0.line;
  s.line1 = e1.line;
  assign_cell(s);
  bd.subs.push_back(s);
}

/// The pieces of a segment between consecutive sorted events (bd.events): one Sub each.
void emit_segment_subs(Builder& bd) {
  const auto& ev = bd.events;
  for (std::size_t j = 0; j + 1 < ev.size(); ++j) {
    if (ev[j].p == ev[j + 1].p) continue;
    push_sub(Sub{}, ev[j], ev[j + 1], bd);
  }
}

/// The segment a-b's crossings of the vertical (kind = kVertical: x = j) or horizontal
/// (kHorizontal: z = j) grid lines of the window strictly between its ends, as events along it.
template <int kind>
void line_crossings(const Vec2 a, const Vec2 b, Builder& bd) {
  const double a_c = kind == kVertical ? a.x : a.z, b_c = kind == kVertical ? b.x : b.z;
  if (a_c == b_c) return;
  const int lo = kind == kVertical ? bd.W.i0 : bd.W.k0, hi = kind == kVertical ? bd.W.i1 : bd.W.k1;
  const int j0 = std::max(lo, floor_int(std::min(a_c, b_c)) + 1);
  const int j1 = std::min(hi, static_cast<int>(std::ceil(std::max(a_c, b_c))) - 1);
  for (int j = j0; j <= j1; ++j) {
    const double c = cross_at<kind>(a, b, j);
    const Vec2 p = kind == kVertical ? Vec2{double(j), c} : Vec2{c, double(j)};
    bd.events.push_back({(j - a_c) / (b_c - a_c), p, {kind, j}});
  }
}

/// Coverage events of the segment a-b on the vertical (kVertical) or horizontal lines of B it
/// reaches, for the lines shifted by +eps (plus) and -eps (minus).
template <int kind>
void line_coverage(const Vec2 a, const Vec2 b, Builder& bd) {
  const double a_c = kind == kVertical ? a.x : a.z, b_c = kind == kVertical ? b.x : b.z;
  // The sign of the crossing: +1 towards larger xi on a vertical line; along a horizontal line
  // the solid is on the left: travelling -zeta, it lies at +xi (the sign flips).
  const int dir = (b_c > a_c) == (kind == kVertical) ? 1 : -1;
  const int lo = kind == kVertical ? bd.B.i0 : bd.B.k0, hi = kind == kVertical ? bd.B.i1 : bd.B.k1;
  auto& plus = kind == kVertical ? bd.ex_plus : bd.ez_plus;
  auto& minus = kind == kVertical ? bd.ex_minus : bd.ez_minus;
  for (int j = std::max(lo, static_cast<int>(std::ceil(std::min(a_c, b_c))));
       j <= std::min(hi, floor_int(std::max(a_c, b_c))); ++j) {
    if ((a_c > j) != (b_c > j)) plus[j - lo].push_back({cross_at<kind>(a, b, j), dir});
    if ((a_c >= j) != (b_c >= j)) minus[j - lo].push_back({cross_at<kind>(a, b, j), dir});
  }
}

/// Splits the segment a-b at the grid lines and adds its crossings of the shifted lines.
void split_segment(const Vec2 a, const Vec2 b, Builder& bd) {
  auto& ev = bd.events;
  ev.clear();
  ev.push_back({0.0, a, {}});
  line_crossings<kVertical>(a, b, bd);
  line_crossings<kHorizontal>(a, b, bd);
  std::sort(ev.begin() + 1, ev.end(), [](const Event& p, const Event& q) { return p.t < q.t; });
  ev.push_back({1.0, b, {}});
  emit_segment_subs(bd);
  line_coverage<kVertical>(a, b, bd);
  line_coverage<kHorizontal>(a, b, bd);
}

// ---- arcs ------------------------------------------------------------------------------------

/// An angle a brought into [f0, f0 + 2 pi).
double wrap_angle(double a, double f0) {
  double t = std::fmod(a - f0, kTwoPi);
  if (t < 0) t += kTwoPi;
  return f0 + t;
}

/// The angular distance between a and b, in [0, pi].
double angle_gap(double a, double b) {
  const double t = std::fabs(std::fmod(a - b, kTwoPi));
  return std::min(t, kTwoPi - t);
}

/// An arc seen across one family of grid lines (vertical: the lines xi = j; horizontal: zeta = j).
/// "across" is the coordinate the lines are numbered by, "along" the one running along them.
struct ArcAxis {
  bool vert = true;
  double cc = 0, ca = 0;    // centre across, along
  double a_c = 0, b_c = 0;  // end points across
  double a_l = 0, b_l = 0;  // end points along
  int lo = 0, hi = 0;       // lines of B
  std::vector<std::vector<std::pair<double, int>>>*plus = nullptr, *minus = nullptr;
  double f0 = 0, f1 = 0, delta = 0;  // the arc's angles; delta: a short step inside it

  /// Motion across the lines just after the start (start = true) or just before the end: > 0
  /// when the coordinate across the lines grows.
  double grow(bool start) const {
    const double mid = start ? f0 + 0.5 * delta : f1 - 0.5 * delta;
    return vert ? -std::sin(mid) : std::cos(mid);
  }
  /// The sweep counts +1 for a crossing of a vertical line towards +xi and of a horizontal line
  /// towards -zeta.
  int dir_of(double g) const { return (g > 0) == vert ? 1 : -1; }
};

ArcAxis arc_axis(const UPiece& p, Builder& bd, int axis) {
  ArcAxis x;
  x.vert = axis == 0;
  const bool vert = x.vert;
  x.cc = vert ? p.c.x : p.c.z, x.ca = vert ? p.c.z : p.c.x;
  x.a_c = vert ? p.a.x : p.a.z, x.b_c = vert ? p.b.x : p.b.z;
  x.a_l = vert ? p.a.z : p.a.x, x.b_l = vert ? p.b.z : p.b.x;
  x.lo = vert ? bd.B.i0 : bd.B.k0, x.hi = vert ? bd.B.i1 : bd.B.k1;
  x.plus = vert ? &bd.ex_plus : &bd.ez_plus;
  x.minus = vert ? &bd.ex_minus : &bd.ez_minus;
  x.f0 = p.phi0, x.f1 = p.phi1;
  x.delta = std::min(x.f1 - x.f0, 1e-3);
  return x;
}

/// A crossing of the full circle with a grid line.
struct Root {
  double ang, along;
  int dir;
  bool inside;  // within the arc's angle range (not at an end point on the line)
};

/// The circle's crossings of line j (0 or 2), decided exactly (compare_distance).
int arc_line_roots(const UPiece& p, const ArcAxis& x, int j, Root r[2]) {
  if (compare_distance(j, x.cc, p.rho) >= 0) return 0;
  const double d = j - x.cc;
  const double s = std::sqrt(std::max(0.0, (p.rho - d) * (p.rho + d)));
  if (x.vert) {
    r[0] = {wrap_angle(std::atan2(-s, d), x.f0), x.ca - s, 1, false};
    r[1] = {wrap_angle(std::atan2(s, d), x.f0), x.ca + s, -1, false};
  } else {
    r[0] = {wrap_angle(std::atan2(d, -s), x.f0), x.ca - s, 1, false};
    r[1] = {wrap_angle(std::atan2(d, s), x.f0), x.ca + s, -1, false};
  }
  for (int q = 0; q < 2; ++q) {
    // A crossing at an end point lying exactly on the line is handled by that end point.
    const bool at_end = (x.a_c == j && angle_gap(r[q].ang, x.f0) < 1e-6) ||
                        (x.b_c == j && angle_gap(r[q].ang, x.f1) < 1e-6);
    r[q].inside = !at_end && r[q].ang > x.f0 && r[q].ang < x.f1;
  }
  return 2;
}

/// The arc's crossings of line j shifted by +eps (e = 0; points on it count as below) and by
/// -eps (e = 1), checked against the sides of the arc's end points (exact comparisons), which
/// settles the cases where a crossing and an end point coincide.
void arc_line_coverage(const ArcAxis& x, int j, const Root r[2], int nr) {
  for (int e = 0; e < 2; ++e) {
    const bool sa = e == 0 ? x.a_c > j : x.a_c >= j, sb = e == 0 ? x.b_c > j : x.b_c >= j;
    auto& out = (e == 0 ? *x.plus : *x.minus)[j - x.lo];
    int crossings = 0;
    if (x.a_c == j) {
      const double g = x.grow(true);
      if ((e == 0) == (g > 0)) out.push_back({x.a_l, x.dir_of(g)}), ++crossings;
    }
    if (x.b_c == j) {
      const double g = x.grow(false);
      if ((e == 0) == (g < 0)) out.push_back({x.b_l, x.dir_of(g)}), ++crossings;
    }
    bool inc[2] = {nr > 0 && r[0].inside, nr > 0 && r[1].inside};
    crossings += (inc[0] ? 1 : 0) + (inc[1] ? 1 : 0);
    if ((crossings % 2 == 1) != (sa != sb)) {
      // A crossing within round-off of an end point that is not on the line: trust the end
      // points' sides (exact) and flip the crossing nearest to an end.
      int best = -1;
      double best_gap = 1e-6;
      for (int q = 0; q < nr; ++q) {
        const double g = std::min(angle_gap(r[q].ang, x.f0), angle_gap(r[q].ang, x.f1));
        if (g < best_gap) best_gap = g, best = q;
      }
      if (best >= 0) inc[best] = !inc[best];
    }
    for (int q = 0; q < nr; ++q) {
      if (inc[q]) out.push_back({r[q].along, r[q].dir});
    }
  }
}

/// The arc pieces between consecutive sorted events (angles in bd.events): one Sub each.
void emit_arc_subs(const UPiece& p, Builder& bd) {
  const auto& ev = bd.events;
  for (std::size_t j = 0; j + 1 < ev.size(); ++j) {
    const double dphi = ev[j + 1].t - ev[j].t;
    if (dphi <= 0.0 || (ev[j].p == ev[j + 1].p && dphi < M_PI)) continue;
    Sub s;
    s.arc = true;
    s.c = p.c;
    s.rho = p.rho;
    s.phi0 = ev[j].t;
    s.dphi = dphi;
    push_sub(s, ev[j], ev[j + 1], bd);
  }
}

/// Splits an arc at the grid lines and adds its crossings of the lines shifted by +eps and -eps.
void split_arc(const UPiece& p, Builder& bd) {
  auto& ev = bd.events;
  ev.clear();
  ev.push_back({p.phi0, p.a, {}});
  for (int axis = 0; axis < 2; ++axis) {
    const ArcAxis x = arc_axis(p, bd, axis);
    for (int j = std::max(x.lo, floor_int(x.cc - p.rho));
         j <= std::min(x.hi, floor_int(x.cc + p.rho) + 1); ++j) {
      Root r[2];
      const int nr = arc_line_roots(p, x, j, r);
      const Line line{x.vert ? kVertical : kHorizontal, j};
      for (int q = 0; q < nr; ++q) {
        if (!r[q].inside) continue;
        ev.push_back(
            {r[q].ang, x.vert ? Vec2{double(j), r[q].along} : Vec2{r[q].along, double(j)}, line});
      }
      arc_line_coverage(x, j, r, nr);
    }
  }
  std::sort(ev.begin() + 1, ev.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
  ev.push_back({p.phi1, p.b, {}});
  emit_arc_subs(p, bd);
}

// ---- full circles ----------------------------------------------------------------------------

/// A full circle's crossings of the lines of B: covered intervals (bd.lx, bd.lz) and, on the
/// lines of W, events at their angles in [0, 2 pi): on a vertical line the lower crossing first,
/// on a horizontal line the right one first.
void circle_crossings(const Vec2 c, const double rho, Builder& bd) {
  for (int axis = 0; axis < 2; ++axis) {
    const bool vert = axis == 0;
    const double cc = vert ? c.x : c.z, ca = vert ? c.z : c.x;  // centre across, along the lines
    const int lo = vert ? bd.B.i0 : bd.B.k0, hi = vert ? bd.B.i1 : bd.B.k1;
    const int w_lo = vert ? bd.W.i0 : bd.W.k0, w_hi = vert ? bd.W.i1 : bd.W.k1;
    auto& lines = vert ? bd.lx : bd.lz;
    for (int j = std::max(lo, floor_int(cc - rho)); j <= std::min(hi, floor_int(cc + rho) + 1);
         ++j) {
      if (compare_distance(j, cc, rho) >= 0) continue;
      const double d = j - cc;
      // s = sqrt(rho^2 - d^2)
      const double s = std::sqrt(std::max(0.0, (rho - d) * (rho + d)));
      lines[j - lo].push_back({ca - s, ca + s});
      if (j < w_lo || j > w_hi) continue;
      for (const bool below : {vert, !vert}) {
        const double off = below ? -s : s, along = below ? ca - s : ca + s;
        double ang = vert ? std::atan2(off, d) : std::atan2(d, off);
        if (ang < 0) ang += kTwoPi;
        bd.events.push_back({ang,
                             vert ? Vec2{double(j), along} : Vec2{along, double(j)},
                             {vert ? kVertical : kHorizontal, j}});
      }
    }
  }
}

void split_circle(const Item& it, Builder& bd) {
  auto& ev = bd.events;
  ev.clear();
  const Vec2 c = it.c;
  const double rho = it.rho;
  circle_crossings(c, rho, bd);
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
    s.dphi = dphi;
    push_sub(s, e0, e1, bd);
  }
}

}  // namespace

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

void split_item(const Item& it, Builder& bd) {
  if (it.circle) {
    split_circle(it, bd);
    return;
  }
  if (!it.loop.empty()) {
    for (const auto& p : it.loop) {
      if (p.arc) {
        split_arc(p, bd);
      } else {
        split_segment(p.a, p.b, bd);
      }
    }
  } else {
    const std::size_t n = it.verts.size();
    for (std::size_t e = 0; e < n; ++e) split_segment(it.verts[e], it.verts[(e + 1) % n], bd);
  }
  finish_coverage(bd);
}

}  // namespace picdem::geometry::detail

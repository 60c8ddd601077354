// Open tank sides: the inflow profiles, their exact time integrals, and the open/ keys
// (open_boundary.hpp, doc/open_boundaries.md).
#include "picdem/fluid/open_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace picdem::fluid {

namespace {

const char* const kSideNames[4] = {"left", "right", "bottom", "top"};

/// Linear interpolation of the values y at x over the increasing nodes xs, constant beyond.
double interpolate(const std::vector<double>& xs, const double* y, double x) {
  if (x <= xs.front()) return y[0];
  if (x >= xs.back()) return y[xs.size() - 1];
  const auto it = std::upper_bound(xs.begin(), xs.end(), x);
  const auto m = static_cast<std::size_t>(it - xs.begin());
  const double a = (x - xs[m - 1]) / (xs[m] - xs[m - 1]);
  return (1.0 - a) * y[m - 1] + a * y[m];
}

/// The side's extent along it: [lo, hi].
std::array<double, 2> side_extent(const grid::GridSpec& g, std::size_t side) {
  return side < 2 ? std::array<double, 2>{g.origin.z, g.origin.z + g.height()}
                  : std::array<double, 2>{g.origin.x, g.origin.x + g.length()};
}

bool increasing(const std::vector<double>& v) {
  for (std::size_t n = 1; n < v.size(); ++n)
    if (!(v[n] > v[n - 1])) return false;
  return true;
}

}  // namespace

double OpenSide::speed(double s, double t) const {
  switch (shape) {
    case InflowShape::Uniform:
      return velocity;
    case InflowShape::Parabolic: {
      // u = 4 U (s - a)(b - s) / (b - a)^2 over the range [a, b] (peak U at the middle)
      const double L = to - from;
      return L > 0.0 ? std::max(0.0, 4.0 * velocity * (s - from) * (to - s) / (L * L)) : 0.0;
    }
    case InflowShape::Table: {
      const std::size_t M = heights.size();
      std::vector<double> at(times.size());
      for (std::size_t l = 0; l < times.size(); ++l) at[l] = interpolate(heights, &table[l * M], s);
      return interpolate(times, at.data(), t);
    }
  }
  return 0.0;
}

double OpenSide::displacement(double s, double t) const {
  if (t <= 0.0) return 0.0;
  if (shape != InflowShape::Table) return speed(s, 0.0) * t;  // steady
  const std::size_t M = heights.size(), L = times.size();
  std::vector<double> v(L);
  for (std::size_t l = 0; l < L; ++l) v[l] = interpolate(heights, &table[l * M], s);
  // S = integral over [0, t] of the speed, linear in time between the entries, constant outside
  double S = 0.0, a = 0.0;  // a: integrated up to here
  if (times.front() > 0.0) {
    const double b = std::min(t, times.front());
    S += v.front() * (b - a);
    a = b;
  }
  for (std::size_t l = 0; l + 1 < L && a < t; ++l) {
    const double lo = std::max(a, times[l]), hi = std::min(t, times[l + 1]);
    if (hi <= lo) continue;
    const double span = times[l + 1] - times[l];
    auto at = [&](double x) { return v[l] + (v[l + 1] - v[l]) * (x - times[l]) / span; };
    S += 0.5 * (at(lo) + at(hi)) * (hi - lo);  // trapezoid: exact for a linear speed
    a = hi;
  }
  const double last = std::max(a, times.back());
  if (t > last) S += v.back() * (t - last);
  return S;
}

std::array<double, 2> OpenSide::displacement_bounds(double s0, double s1, double t) const {
  // Extremes at the ends, the parabola's vertex or the table's heights (piecewise linear in s).
  std::vector<double> at{s0, s1};
  if (shape == InflowShape::Parabolic) at.push_back(0.5 * (from + to));
  if (shape == InflowShape::Table) at.insert(at.end(), heights.begin(), heights.end());
  std::array<double, 2> b{displacement(s0, t), displacement(s0, t)};
  for (double s : at)
    if (s >= s0 && s <= s1) {
      const double S = displacement(s, t);
      b[0] = std::min(b[0], S), b[1] = std::max(b[1], S);
    }
  return b;
}

bool OpenBoundaries::any() const {
  return std::any_of(side.begin(), side.end(),
                     [](const auto& s) { return s.kind != OpenKind::Wall; });
}

bool OpenBoundaries::any_inflow() const {
  return std::any_of(side.begin(), side.end(),
                     [](const auto& s) { return s.kind == OpenKind::Inflow; });
}

double OpenBoundaries::max_inflow_speed(double t) const {
  double v = 0.0;
  for (const OpenSide& o : side) {
    if (o.kind != OpenKind::Inflow) continue;
    if (o.shape != InflowShape::Table) {
      v = std::max(v, std::abs(o.velocity));  // uniform, or the parabola's peak
      continue;
    }
    // bilinear in (s, t): the largest magnitude at time t lies at one of the table's heights
    for (double s : o.heights) v = std::max(v, std::abs(o.speed(s, t)));
  }
  return v;
}

double OpenBoundaries::face_speed(std::size_t n, double s) const {
  const OpenSide& o = side[n];
  if (!(t1 > t0)) return o.speed(s, t0);
  // u_face = (S(t1) - S(t0)) / (t1 - t0)
  return (o.displacement(s, t1) - o.displacement(s, t0)) / (t1 - t0);
}

double face_position(const grid::GridSpec& g, std::size_t side, int f) {
  return (side < 2 ? g.origin.z : g.origin.x) + (f + 0.5) * g.h;
}

int side_faces(const grid::GridSpec& g, std::size_t side) {
  return side < 2 ? g.nz : g.nx;
}

bool outflow_beyond(const OpenBoundaries& o, const grid::GridSpec& g, int i, int k, int ni,
                    int nk) {
  std::size_t side;
  if (ni < 0)
    side = 0;
  else if (ni >= g.nx)
    side = 1;
  else if (nk < 0)
    side = 2;
  else
    side = 3;
  const OpenSide& s = o.side[side];
  return s.kind == OpenKind::Outflow && s.open_at(face_position(g, side, side < 2 ? k : i));
}

void declare_open_parameters(core::ParamSchema& schema) {
  schema.section("open",
                 "Open tank sides: inflow with a prescribed velocity that injects particles, "
                 "outflow (p = 0, do-nothing viscous stress) that removes them "
                 "(doc/open_boundaries.md).");
  for (const char* side : kSideNames) {
    const std::string p = std::string("open/") + side + "/";
    schema.string(
        p + "type", "wall", {"wall", "inflow", "outflow"},
        std::string("the ") + side + " side: a wall (fluid/walls), an inflow or an outflow");
    schema
        .reals(p + "range", {},
               "[from, to]: the open part of the side, as a coordinate along it (z on the left "
               "and right sides, x on the bottom and top) [m]; faces whose centre lies in it are "
               "open; empty: the whole side")
        .size(0, 2);
    schema.string(p + "profile", "uniform", {"uniform", "parabolic", "table"},
                  "inflow velocity over the range: uniform, parabolic (0 at the range's ends), "
                  "or a table over position and time");
    schema
        .real(p + "velocity", 0.0,
              "inflow: the inward speed (uniform) or its peak at the range's middle (parabolic) "
              "[m/s]")
        .non_negative();
    schema.string(p + "outflow_velocity", "projected", {"projected", "zero_gradient"},
                  "outflow: the outflow faces' velocity before the projection: their own "
                  "(projected) or that of the interior faces next to them (zero_gradient, "
                  "du_n / dn = 0); p = 0 on the faces either way");
    schema.reals(p + "heights", {}, "table: positions along the side, increasing [m]");
    schema.reals(p + "times", {}, "table: times, increasing, >= 0 [s]").non_negative();
    schema
        .reals(p + "table", {},
               "table: inward speeds [m/s], one row of len(heights) values per time, bilinear, "
               "constant beyond the ends")
        .non_negative();
  }
  schema.check([](const core::Params& params, std::vector<std::string>& errors) {
    if (!params.has("grid/cell_size")) return;  // a schema without the grid (unit tests)
    const grid::GridSpec g = grid::spec_from(params);
    for (std::size_t n = 0; n < 4; ++n) {
      const std::string p = std::string("open/") + kSideNames[n] + "/";
      const std::string type = params.string(p + "type");
      const auto range = params.reals(p + "range");
      const auto ext = side_extent(g, n);
      std::ostringstream e;
      if (range.size() == 1 ||
          (range.size() == 2 && !(range[0] >= ext[0] && range[0] < range[1] && range[1] <= ext[1])))
        e << "key '" << p << "range' must be empty or [from, to] with " << ext[0]
          << " <= from < to <= " << ext[1] << " (the " << kSideNames[n] << " side)";
      const std::string profile = params.string(p + "profile");
      const double v = params.real(p + "velocity");
      const auto heights = params.reals(p + "heights"), times = params.reals(p + "times"),
                 table = params.reals(p + "table");
      if (type != "inflow" && (v > 0.0 || !table.empty() || profile != "uniform"))
        e << "keys '" << p << "velocity', 'profile' and 'table' belong to an inflow, but '" << p
          << "type' is " << type;
      if (type != "outflow" && params.string(p + "outflow_velocity") != "projected")
        e << "key '" << p << "outflow_velocity' belongs to an outflow, but '" << p << "type' is "
          << type;
      if (type == "inflow" && profile != "table" && !(v > 0.0))
        e << "key '" << p << "velocity' = " << v << ": an inflow with the " << profile
          << " profile needs a speed > 0";
      if (type == "inflow" && profile == "table" &&
          (heights.empty() || times.empty() || !increasing(heights) || !increasing(times) ||
           table.size() != heights.size() * times.size()))
        e << "keys '" << p << "heights', 'times', 'table': the table profile needs increasing "
          << "heights and times and len(heights) x len(times) speeds (got " << heights.size()
          << ", " << times.size() << ", " << table.size() << ")";
      if (!e.str().empty()) errors.push_back(e.str());
    }
  });
}

OpenBoundaries open_boundaries_from(const core::Params& params, const grid::GridSpec& g) {
  OpenBoundaries o;
  for (std::size_t n = 0; n < 4; ++n) {
    const std::string p = std::string("open/") + kSideNames[n] + "/";
    OpenSide& s = o.side[n];
    const std::string type = params.string(p + "type");
    s.kind = type == "inflow" ? OpenKind::Inflow
                              : (type == "outflow" ? OpenKind::Outflow : OpenKind::Wall);
    const auto range = params.reals(p + "range");
    const auto ext = side_extent(g, n);
    s.from = range.size() == 2 ? range[0] : ext[0];
    s.to = range.size() == 2 ? range[1] : ext[1];
    const std::string profile = params.string(p + "profile");
    s.shape = profile == "parabolic"
                  ? InflowShape::Parabolic
                  : (profile == "table" ? InflowShape::Table : InflowShape::Uniform);
    s.velocity = params.real(p + "velocity");
    s.heights = params.reals(p + "heights");
    s.times = params.reals(p + "times");
    s.table = params.reals(p + "table");
    s.zero_gradient = params.string(p + "outflow_velocity") == "zero_gradient";
  }
  return o;
}

}  // namespace picdem::fluid

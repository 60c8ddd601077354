// The `graded_packing` generator (doc/shapes.md): sizes from a grading curve, a shape and a
// density per class, placed by place_packing (packing_placement.cpp).
#include "picdem/geometry/graded_packing.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::geometry {

namespace {

std::string join(const std::vector<double>& v) {
  std::ostringstream m;
  m << "[";
  for (std::size_t i = 0; i < v.size(); ++i) m << (i ? ", " : "") << v[i];
  return m.str() + "]";
}

/// Number weight of the interval [a, b] carrying the fraction w of the curve. By mass with
/// the mass fraction linear in ln d, the mass density is w / (d ln(b/a)) and the number density
/// that divided by d^2 (mass ~ d^2): integral w (a^-2 - b^-2) / (2 ln(b/a)). By number: w.
double number_weight(double a, double b, double w, bool by_mass) {
  if (!by_mass) return w;
  return w * (1.0 / (a * a) - 1.0 / (b * b)) / (2.0 * std::log(b / a));
}

}  // namespace

GradingCurve::GradingCurve(std::vector<double> sieves, std::vector<double> passing, bool by_mass,
                           const std::string& what)
    : sieves_(std::move(sieves)), passing_(std::move(passing)), by_mass_(by_mass) {
  const auto bad = [&](const std::string& key, const std::string& why) {
    throw core::InputError(what + "/" + key + " = " + join(key == "sieves" ? sieves_ : passing_) +
                           ": " + why);
  };
  if (sieves_.size() < 2) bad("sieves", "needs at least two sizes");
  if (passing_.size() != sieves_.size())
    bad("passing", "needs one fraction per sieve (" + std::to_string(sieves_.size()) + ")");
  for (std::size_t k = 0; k < sieves_.size(); ++k) {
    if (!(sieves_[k] > 0.0) || !std::isfinite(sieves_[k])) bad("sieves", "sizes must be > 0");
    if (k > 0 && !(sieves_[k] > sieves_[k - 1])) bad("sieves", "sizes must increase strictly");
    if (k > 0 && !(passing_[k] >= passing_[k - 1])) bad("passing", "fractions must not decrease");
  }
  if (passing_.front() != 0.0 || passing_.back() != 1.0)
    bad("passing", "must be 0 at the smallest sieve (d_min) and 1 at the largest (d_max)");
  number_cdf_.assign(1, 0.0);
  for (std::size_t k = 0; k + 1 < sieves_.size(); ++k)
    number_cdf_.push_back(number_cdf_.back() + number_weight(sieves_[k], sieves_[k + 1],
                                                             passing_[k + 1] - passing_[k],
                                                             by_mass_));
  for (double& c : number_cdf_) c /= number_cdf_.back();
}

double GradingCurve::sample(double u) const {
  std::size_t k = 0;
  while (k + 2 < number_cdf_.size() && !(u < number_cdf_[k + 1])) ++k;
  const double a = sieves_[k], b = sieves_[k + 1];
  const double width = number_cdf_[k + 1] - number_cdf_[k];
  const double s = width > 0.0 ? std::clamp((u - number_cdf_[k]) / width, 0.0, 1.0) : 0.0;
  // by number, uniform in ln d: d = a (b/a)^s; by mass the number density ~ d^-3:
  // d^-2 = a^-2 - s (a^-2 - b^-2)
  if (!by_mass_) return a * std::pow(b / a, s);
  return 1.0 / std::sqrt(1.0 / (a * a) - s * (1.0 / (a * a) - 1.0 / (b * b)));
}

double GradingCurve::passing_at(double d) const {
  if (d <= sieves_.front()) return 0.0;
  if (d >= sieves_.back()) return 1.0;
  std::size_t k = 0;
  while (d > sieves_[k + 1]) ++k;
  const double s = std::log(d / sieves_[k]) / std::log(sieves_[k + 1] / sieves_[k]);
  return passing_[k] + s * (passing_[k + 1] - passing_[k]);
}

namespace {

enum class ClassShape { Disk, Polygon, Ellipse };

/// One class of the packing: its shape kind, density (0: the entry's) and share.
struct PackingClass {
  ClassShape shape = ClassShape::Disk;
  double density = 0.0;
  double fraction = 1.0;
};

std::vector<PackingClass> classes_of(const core::Params& s) {
  std::vector<PackingClass> out;
  std::stringstream list(s.string("class_shapes"));
  std::string name;
  while (std::getline(list, name, ',')) {
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    PackingClass c;
    if (name == "disk")
      c.shape = ClassShape::Disk;
    else if (name == "polygon")
      c.shape = ClassShape::Polygon;
    else if (name == "ellipse")
      c.shape = ClassShape::Ellipse;
    else
      throw core::InputError(s.full_path("class_shapes") + " = '" + s.string("class_shapes") +
                             "': shape '" + name +
                             "' is not known; allowed: disk, polygon, "
                             "ellipse (comma separated, one per class)");
    out.push_back(c);
  }
  const auto fractions = s.reals("class_fractions"), densities = s.reals("class_densities");
  const auto count_error = [&](const std::string& key, const std::vector<double>& v) {
    throw core::InputError(s.full_path(key) + " = " + join(v) + ": needs one value per class (" +
                           std::to_string(out.size()) + " in class_shapes)");
  };
  if (!fractions.empty() && fractions.size() != out.size())
    count_error("class_fractions", fractions);
  if (!densities.empty() && densities.size() != out.size())
    count_error("class_densities", densities);
  double total = 0.0;
  for (std::size_t c = 0; c < out.size(); ++c) {
    out[c].fraction = fractions.empty() ? 1.0 : fractions[c];
    out[c].density = densities.empty() ? 0.0 : densities[c];
    total += out[c].fraction;
  }
  if (!(total > 0.0)) count_error("class_fractions", fractions);
  for (auto& c : out) c.fraction /= total;
  return out;
}

GradingCurve curve_of(const core::Params& s) {
  const bool by_mass = s.string("basis") == "mass";
  const auto sieves = s.reals("sieves");
  const double d_min = s.real("d_min"), d50 = s.real("d50"), d_max = s.real("d_max");
  const bool three = d_min > 0.0 || d50 > 0.0 || d_max > 0.0;
  if (three == !sieves.empty())
    throw core::InputError(s.full_path("sieves") +
                           ": give either sieves and passing, or d_min, d50 and d_max");
  const std::string where = s.full_path("sieves").substr(0, s.full_path("sieves").size() - 7);
  if (!three) return GradingCurve(sieves, s.reals("passing"), by_mass, where);
  if (!(d_min > 0.0 && d_min < d50 && d50 < d_max)) {
    std::ostringstream m;
    m << s.full_path("d50") << ": d_min = " << d_min << ", d50 = " << d50 << ", d_max = " << d_max
      << ": allowed 0 < d_min < d50 < d_max";
    throw core::InputError(m.str());
  }
  return GradingCurve({d_min, d50, d_max}, {0.0, 0.5, 1.0}, by_mass, where);
}

/// A convex polygon with n vertices on a circle at jittered angles, scaled to area pi d^2 / 4.
ShapePtr random_polygon(double d, long long n, PackingRandom& rng) {
  std::vector<Vec2> v;
  for (long long q = 0; q < n; ++q) {
    // consecutive angles at least pi / n apart: points on a circle in order are convex
    const double phi = 2.0 * M_PI * (static_cast<double>(q) + 0.5 * rng.uniform()) / n;
    v.push_back({std::cos(phi), std::sin(phi)});
  }
  const double scale = std::sqrt(0.25 * M_PI * d * d / polygon_properties(v).area);
  for (auto& p : v) p = scale * p;
  return std::make_shared<const Polygon>(v);
}

PackingItem draw_item(const core::Params& s, const GradingCurve& curve,
                      const std::vector<PackingClass>& classes, PackingRandom& rng) {
  PackingItem it;
  it.size = curve.sample(rng.uniform());
  const double u = rng.uniform();
  std::size_t c = 0;
  for (double acc = classes[0].fraction; c + 1 < classes.size() && u >= acc;)
    acc += classes[++c].fraction;
  it.density = classes[c].density;
  if (classes[c].shape == ClassShape::Disk) {
    it.shape = std::make_shared<const Circle>(0.5 * it.size);
    return it;
  }
  it.theta = 2.0 * M_PI * rng.uniform();
  if (classes[c].shape == ClassShape::Polygon) {
    const auto nv = s.reals("vertices");
    it.shape = random_polygon(it.size, rng.integer(std::llround(nv[0]), std::llround(nv[1])), rng);
  } else {
    const auto asp = s.reals("aspect");
    // a / b = k and a b = d^2 / 4 (area pi d^2 / 4)
    const double k = asp[0] + (asp[1] - asp[0]) * rng.uniform();
    it.shape = make_ellipse(0.5 * it.size * std::sqrt(k), 0.5 * it.size / std::sqrt(k));
  }
  return it;
}

void declare_graded_packing(core::ParamSchema& v) {
  v.reals("region", {}, "box x0, z0, x1, z1 the solids are placed in [m]").size(4, 4).is_required();
  v.string("placement", "box", {"box", "pour"},
           "box: random sequential addition in the box, largest first; pour: each solid dropped "
           "down the lowest of `drops` random columns onto the floor or the solids below");
  v.integer("count", 0, "number of solids (0: from solid_fraction)").at_least(0);
  v.real("solid_fraction", 0.0, "solids' area over the region's area (0: from count)")
      .non_negative()
      .less_than(1.0);
  v.reals("sieves", {}, "grading curve: sieve sizes, increasing [m]");
  v.reals("passing", {}, "grading curve: fraction passing each sieve, 0 ... 1");
  v.real("d_min", 0.0, "grading curve instead of sieves: smallest size [m]").non_negative();
  v.real("d50", 0.0, "grading curve instead of sieves: median size [m]").non_negative();
  v.real("d_max", 0.0, "grading curve instead of sieves: largest size [m]").non_negative();
  v.string("basis", "mass", {"mass", "number"}, "passing fractions of mass or of number");
  v.string("class_shapes", "disk", {},
           "shape of each class, comma separated: disk, polygon, ellipse");
  v.reals("class_fractions", {}, "share of the solids (by number) in each class (empty: equal)")
      .non_negative();
  v.reals("class_densities", {}, "density of each class [kg/m^3] (empty: `density`)").positive();
  v.reals("vertices", {5.0, 8.0}, "polygon classes: vertex count range [min, max]")
      .size(2, 2)
      .at_least(3.0);
  v.reals("aspect", {1.5, 2.0}, "ellipse classes: a / b range [min, max]")
      .size(2, 2)
      .at_least(1.0)
      .at_most(ellipse_max_aspect);
  v.integer("seed", 1, "random seed (the same packing on every rank)").at_least(0);
  v.integer("tries", 1000, "box: random positions tried per solid").at_least(1);
  v.integer("drops", 8, "pour: columns tried per solid").at_least(1);
  v.real("gap", 0.0, "gap between real boundaries [m] (0: dem/gap_cells x grid/cell_size)")
      .non_negative();
}

}  // namespace

ShapeType graded_packing_type() {
  ShapeType t;
  t.name = "graded_packing";
  t.doc = "solids with sizes from a grading curve, a shape and density per class, placed apart";
  t.declare = declare_graded_packing;
  t.build = [](const core::Params& s, const BuildContext& ctx) {
    const GradingCurve curve = curve_of(s);
    const auto classes = classes_of(s);
    const auto r = s.reals("region");
    PackingRegion box{r[0],
                      r[1],
                      r[2],
                      r[3],
                      s.string("placement") == "pour",
                      s.integer("tries"),
                      s.integer("drops")};
    const double area = (box.x1 - box.x0) * (box.z1 - box.z0);
    if (!(area > 0.0))
      throw core::InputError(s.full_path("region") + " = " + join(r) +
                             ": needs x0 < x1 and z0 < z1");
    const long long count = s.integer("count");
    const double fraction = s.real("solid_fraction");
    if ((count > 0) == (fraction > 0.0))
      throw core::InputError(s.full_path("count") + ": give either count or solid_fraction");
    const auto nv = s.reals("vertices"), asp = s.reals("aspect");
    if (nv[0] > nv[1] || asp[0] > asp[1])
      throw core::InputError(s.full_path(nv[0] > nv[1] ? "vertices" : "aspect") +
                             ": needs [min, max] with min <= max");
    PackingRandom rng(static_cast<std::uint64_t>(s.integer("seed")));
    std::vector<PackingItem> items;
    double filled = 0.0;
    while (count > 0 ? static_cast<long long>(items.size()) < count : filled < fraction * area) {
      items.push_back(draw_item(s, curve, classes, rng));
      filled += items.back().shape->mass_properties().area;
    }
    const double gap = s.real("gap") > 0.0 ? s.real("gap") : ctx.gap;
    const std::string where = s.full_path("region").substr(0, s.full_path("region").size() - 7);
    return place_packing(std::move(items), box, gap, where, rng);
  };
  return t;
}

}  // namespace picdem::geometry

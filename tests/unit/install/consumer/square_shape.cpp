// A shape that picdem does not ship, built against the installed package: a square of side a,
// centred on its centre of mass. picdem's geometry gives its area and polar moment from its
// boundary (loop_properties), its world outline and bounding box; each is compared with the
// closed form (area a^2, polar moment a^4 / 6, corners at a / sqrt(2) from the centre).
#include <cmath>
#include <cstdio>

#include "picdem/geometry/outline.hpp"
#include "picdem/geometry/shape.hpp"

namespace geometry = picdem::geometry;

class Square : public geometry::Shape {
 public:
  explicit Square(double a) : h_(0.5 * a) {}
  std::string kind() const override { return "square"; }
  std::vector<geometry::BoundaryPiece> boundary() const override {
    const geometry::Vec2 c[4] = {{-h_, -h_}, {h_, -h_}, {h_, h_}, {-h_, h_}};
    std::vector<geometry::BoundaryPiece> pieces;
    for (int n = 0; n < 4; ++n) pieces.push_back(geometry::Segment{c[n], c[(n + 1) % 4]});
    return pieces;
  }
  geometry::MassProperties mass_properties() const override {
    const auto r = geometry::loop_properties(boundary());
    return {r.area, r.polar_moment};
  }
  double bounding_radius() const override { return std::sqrt(2.0) * h_; }
  bool contains(const geometry::Vec2& p) const override {
    return std::abs(p.x) <= h_ && std::abs(p.z) <= h_;
  }

 private:
  double h_;
};

int main() {
  const double a = 0.02;
  const Square square(a);
  const auto m = square.mass_properties();
  const geometry::Pose pose{{0.5, 0.3}, 0.4};
  const auto line = geometry::outline(square, pose, 0.001);
  double worst = 0.0;
  for (const auto& p : line)
    worst = std::max(worst, std::abs(std::hypot(p.x - 0.5, p.z - 0.3) - a / std::sqrt(2.0)));
  const auto box = geometry::bounding_box(square, pose);
  const double half_width = 0.5 * a * (std::cos(0.4) + std::sin(0.4));
  const bool ok = std::abs(m.area - a * a) < 1e-15 * a * a &&
                  std::abs(m.polar_moment - std::pow(a, 4) / 6.0) < 1e-15 * std::pow(a, 4) &&
                  line.size() == 5 && worst < 1e-15 &&
                  std::abs(box.hi.x - box.lo.x - 2.0 * half_width) < 1e-15;
  std::printf(
      "square of side %g: area %.17g (a^2 %.17g), polar moment %.17g (a^4/6 %.17g), "
      "outline %zu points within %.1e of the corners' circle, box width %.17g (%.17g): %s\n",
      a, m.area, a * a, m.polar_moment, std::pow(a, 4) / 6.0, line.size(), worst,
      box.hi.x - box.lo.x, 2.0 * half_width, ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}

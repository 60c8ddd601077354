#include "picdem/geometry/circle.hpp"

#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::geometry {

Circle::Circle(double radius) : radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    std::ostringstream m;
    m << "circle radius " << radius << " is not allowed: it must be a finite number > 0";
    throw core::InputError(m.str());
  }
}

std::vector<BoundaryPiece> Circle::boundary() const {
  return {Arc{Vec2{0.0, 0.0}, radius_, 0.0, 2.0 * M_PI}};
}

MassProperties Circle::mass_properties() const {
  // A = pi r^2, J = pi r^4 / 2
  const double r2 = radius_ * radius_;
  return {M_PI * r2, 0.5 * M_PI * r2 * r2};
}

bool Circle::contains(const Vec2& body_point) const {
  return core::norm2(body_point) <= radius_ * radius_;
}

ShapeType disk_type() {
  ShapeType t;
  t.name = "disk";
  t.doc = "a circular cylinder";
  t.declare = [](core::ParamSchema& v) {
    v.real("radius", 0.0, "radius [m]").positive().is_required();
    v.reals("center", {0.0, 0.0}, "initial centre (x, z) [m]").size(2, 2).is_required();
    v.real("theta", 0.0, "initial rotation [rad]");
  };
  t.build = [](const core::Params& s, const BuildContext&) {
    const auto c = s.reals("center");
    return std::vector<PlacedShape>{
        {std::make_shared<const Circle>(s.real("radius")), {{c[0], c[1]}, s.real("theta")}}};
  };
  return t;
}

ShapeType cylinder_stack_type() {
  ShapeType t;
  t.name = "cylinder_stack";
  t.doc =
      "layers of n, n-1, n, ... equal cylinders against a wall, each layer in the hollows of the "
      "one below";
  t.declare = [](core::ParamSchema& v) {
    v.real("radius", 0.0, "cylinder radius [m]").positive().is_required();
    v.integer("layers", 1, "number of layers").at_least(1);
    v.integer("first_layer", 1, "cylinders in the bottom layer (n)").at_least(1);
    v.real("gap", 0.0,
           "gap between neighbours and to the wall and floor [m] (0: dem/gap_cells x "
           "grid/cell_size)")
        .non_negative();
    v.reals("corner", {0.0, 0.0}, "where the wall meets the floor (x, z) [m]").size(2, 2);
    v.string("side", "left", {"left", "right"}, "the wall is on this side of the stack");
  };
  t.build = [](const core::Params& s, const BuildContext& ctx) {
    const double r = s.real("radius");
    double gap = s.real("gap");
    if (gap == 0.0) gap = ctx.gap;
    const auto corner = s.reals("corner");
    const double dir = s.string("side") == "left" ? 1.0 : -1.0;
    const auto n0 = s.integer("first_layer");
    auto shape = std::make_shared<const Circle>(r);
    // neighbours in a layer are 2r + gap apart; a layer sits in the hollows of the one below,
    // touching both at the same gap: rise sqrt(3)/2 (2r + gap)
    const double pitch = 2.0 * r + gap, rise = 0.5 * std::sqrt(3.0) * pitch;
    std::vector<PlacedShape> out;
    for (long long layer = 0; layer < s.integer("layers"); ++layer) {
      const bool short_layer = layer % 2 == 1;
      const long long n = short_layer ? n0 - 1 : n0;
      for (long long c = 0; c < n; ++c) {
        const double along = gap + r + (short_layer ? 0.5 * pitch : 0.0) + c * pitch;
        out.push_back(
            {shape, {{corner[0] + dir * along, corner[1] + gap + r + layer * rise}, 0.0}});
      }
    }
    return out;
  };
  return t;
}

}  // namespace picdem::geometry

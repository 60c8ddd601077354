#include "picdem/geometry/circle.hpp"

#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"

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

}  // namespace picdem::geometry

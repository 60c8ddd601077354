#pragma once
// A disc of radius r, centred on its centre of mass.
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

class Circle : public Shape {
 public:
  /// Throws core::InputError unless radius > 0 and finite.
  explicit Circle(double radius);

  double radius() const { return radius_; }

  std::string kind() const override { return "circle"; }
  /// One full counter-clockwise arc, phi in [0, 2 pi].
  std::vector<BoundaryPiece> boundary() const override;
  /// area = pi r^2, polar moment = pi r^4 / 2.
  MassProperties mass_properties() const override;
  double bounding_radius() const override { return radius_; }
  bool contains(const Vec2& body_point) const override;
  /// The centred-circle fast path (eq. 19 in closed form).
  FastPaths fast_paths() const override { return {radius_}; }

 private:
  double radius_;
};

}  // namespace picdem::geometry

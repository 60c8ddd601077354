#pragma once
// A simple polygon (convex or not) given by its vertices in counter-clockwise order.
#include <string>
#include <vector>

#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

/// Area, centroid and polar second moment (about the centroid) of a simple CCW polygon given in
/// any frame. Throws core::InputError when the polygon is not simple and counter-clockwise.
struct PolygonProperties {
  double area = 0.0;
  Vec2 centroid;
  double polar_moment = 0.0;
};
PolygonProperties polygon_properties(const std::vector<Vec2>& vertices);

/// Throws core::InputError naming `what` when `vertices` has fewer than 3 points, repeats a
/// point, is self-intersecting (CGAL's exact predicates) or is clockwise.
void validate_simple_ccw(const std::vector<Vec2>& vertices, const std::string& what);

class Polygon : public Shape {
 public:
  /// `vertices` in an input frame, counter-clockwise. The polygon is validated (InputError) and
  /// recentred: body-frame vertex = input vertex - centroid_offset().
  explicit Polygon(std::vector<Vec2> vertices);

  /// Reads a vertex file: one "x z" pair per line (whitespace or comma separated), '#' starts a
  /// comment, blank lines ignored. Throws InputError naming the file and line on bad input.
  static Polygon from_file(const std::string& path);

  /// Body-frame vertices (CCW, centroid at the origin).
  const std::vector<Vec2>& vertices() const { return vertices_; }
  /// The centroid of the polygon in the input frame, i.e. where the body origin sits in the
  /// input frame. A pose {x = c + R(theta) * centroid_offset(), theta} places the polygon exactly
  /// where its input vertices, rotated by theta about the input origin c, would be.
  Vec2 centroid_offset() const { return centroid_offset_; }

  std::string kind() const override { return "polygon"; }
  std::vector<BoundaryPiece> boundary() const override;
  MassProperties mass_properties() const override;
  double bounding_radius() const override { return bounding_radius_; }
  /// Inside or on the boundary (exact orientation predicates on the body-frame vertices).
  bool contains(const Vec2& body_point) const override;

 private:
  std::vector<Vec2> vertices_;
  Vec2 centroid_offset_;
  MassProperties mass_;
  double bounding_radius_ = 0.0;
};

}  // namespace picdem::geometry

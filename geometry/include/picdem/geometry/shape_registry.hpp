#pragma once
// Shapes as plug-ins (doc/shapes.md). A shape type declares its case-file keys (one variant of
// the `solids` family), builds its placed shapes from those keys, and is listed once in
// shape_types(). The DEM adds the keys of the motion (density, velocity, omega) to every variant
// and never names a shape.
#include <functional>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

/// A shape placed by a case-file entry at its initial pose.
struct PlacedShape {
  ShapePtr shape;
  Pose pose;
  /// > 0: this shape's own density [kg/m^3] (a generator's class density); 0: the entry's
  /// `density`.
  double density = 0.0;
};

/// What a builder may need beyond its own keys.
struct BuildContext {
  /// The DEM's imaginary gap 2 dx between real boundaries (eq. 19) [m]; 0 when the case sets no
  /// grid. Generators use it as their default spacing.
  double gap = 0.0;
};

struct ShapeType {
  std::string name;  ///< the value of `type` in the case file
  std::string doc;   ///< one line for the parameter reference
  /// Declares the keys of the shape and of its initial pose on the variant's schema.
  std::function<void(core::ParamSchema&)> declare;
  /// The placed shapes of one validated entry (a generator may give several, in id order).
  /// Throws core::InputError naming the key, the value and what is allowed.
  std::function<std::vector<PlacedShape>(const core::Params&, const BuildContext&)> build;
};

/// Every shape type, in the order of the parameter reference.
const std::vector<ShapeType>& shape_types();
/// The type called `name`; core::InputError listing the known names otherwise.
const ShapeType& shape_type(const std::string& name);

/// The numbers x0, z0, x1, z1, ... of the key `key` of `s` as points; core::InputError naming the
/// key when the count is odd.
std::vector<Vec2> vertex_pairs(const core::Params& s, const std::string& key);

// The registered types, one function per shape file; shape_registry.cpp lists them.
ShapeType disk_type();             ///< circle.cpp
ShapeType cylinder_stack_type();   ///< circle.cpp
ShapeType polygon_type();          ///< polygon.cpp
ShapeType polygon_file_type();     ///< polygon.cpp
ShapeType ellipse_type();          ///< ellipse.cpp
ShapeType rounded_polygon_type();  ///< rounded_polygon.cpp
ShapeType graded_packing_type();   ///< graded_packing.cpp

/// The ellipse x^2 / a^2 + z^2 / b^2 <= 1 of the body frame as a G1 convex arc spline
/// (ellipse.cpp, doc/shapes.md): its largest distance to the true ellipse is below
/// ellipse_tolerance(a, b). Throws core::InputError naming `a` or `b` when one is not finite and
/// > 0, or when max(a, b) / min(a, b) exceeds ellipse_max_aspect.
ShapePtr make_ellipse(double a, double b);
/// The bound on the distance between the arc spline and the true ellipse: 1e-4 min(a, b).
double ellipse_tolerance(double a, double b);
/// Largest allowed max(a, b) / min(a, b). The flat sides' arcs have radii near a^2 / b, centres
/// far away, and the cut cells' moments of such arcs lose digits: at aspect 10 the first moments
/// of the wetted boundary stay within 5e-13 of their exact values (tests/unit/geometry), at 20
/// they were 8e-12 off, beyond the 1e-12 the cut-cell invariants are held to.
constexpr double ellipse_max_aspect = 10.0;

/// A convex polygon (CCW vertices, input frame) with every corner rounded by an arc of radius r
/// tangent to both edges, recentred on its centroid like Polygon; `centroid` (if given) gets the
/// centroid in the input frame. Throws core::InputError when r is not finite and > 0, the polygon
/// is not simple, counter-clockwise and convex, or an edge is too short for the arcs at its ends.
ShapePtr make_rounded_polygon(const std::vector<Vec2>& vertices, double r, Vec2* centroid);

}  // namespace picdem::geometry

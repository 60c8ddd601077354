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
ShapeType disk_type();            ///< circle.cpp
ShapeType cylinder_stack_type();  ///< circle.cpp
ShapeType polygon_type();         ///< polygon.cpp
ShapeType polygon_file_type();    ///< polygon.cpp

}  // namespace picdem::geometry

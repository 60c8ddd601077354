#include "picdem/geometry/shape_registry.hpp"

#include "picdem/core/error.hpp"

namespace picdem::geometry {

const std::vector<ShapeType>& shape_types() {
  // A new shape adds one line here (doc/shapes.md).
  static const std::vector<ShapeType> types{disk_type(),         polygon_type(),
                                            polygon_file_type(), cylinder_stack_type(),
                                            ellipse_type(),      rounded_polygon_type(),
                                            graded_packing_type()};
  return types;
}

const ShapeType& shape_type(const std::string& name) {
  std::string known;
  for (const auto& t : shape_types()) {
    if (t.name == name) return t;
    known += (known.empty() ? "" : ", ") + t.name;
  }
  throw core::InputError("solid type '" + name + "' is not known; allowed: " + known);
}

}  // namespace picdem::geometry

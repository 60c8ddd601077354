#pragma once
// Fixed obstacles from the case file: family "obstacles" with variants box, polygon, polyline
// (a thick polyline), fall_pipe (a vertical pipe of two walls, a funnel on top, optionally
// perforated). Every variant becomes a union of CCW simple polygons in the world frame.
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/geometry/cut_cells.hpp"

namespace picdem::geometry {

/// Declares the family `obstacles` and its variants on `schema`.
void declare_obstacle_parameters(core::ParamSchema& schema);

/// The obstacles of validated parameters, in file order (none when the section is absent).
/// Throws core::InputError naming the key for geometry the schema cannot check (a polygon that
/// is self-intersecting or clockwise, a funnel narrower than its pipe, ...).
std::vector<Obstacle> obstacles_from(const core::Params& params);

/// A polyline of the given thickness as one polygon with mitred joints (CCW). `what` names the
/// input in error messages.
std::vector<Vec2> thick_polyline(const std::vector<Vec2>& points, double thickness,
                                 const std::string& what);

struct FallPipe {
  double centre_x = 0.0;
  double inner_width = 0.0;
  double wall_thickness = 0.0;
  double bottom = 0.0, top = 0.0;
  double funnel_top_width = 0.0;  ///< inner width at the funnel's top (>= inner_width)
  double funnel_height = 0.0;     ///< 0: no funnel
  double hole_size = 0.0;         ///< height of each hole through both walls; 0: continuous
  double hole_spacing = 0.0;  ///< distance between hole centres, the first at bottom + spacing/2
};

/// Closed polylines (last point = first) of an obstacle's polygons, for ParaView and PNG output.
std::vector<std::vector<Vec2>> outlines(const Obstacle& obstacle);

/// The walls, funnel and holes of a fall pipe as CCW polygons.
std::vector<std::vector<Vec2>> fall_pipe_polygons(const FallPipe& pipe, const std::string& what);

}  // namespace picdem::geometry

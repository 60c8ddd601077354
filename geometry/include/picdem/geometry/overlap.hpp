#pragma once
// How deep two outlines overlap, exactly, for the checks before a run (doc/geometry.md,
// "Overlap depth"): convex outlines by their support functions, non-convex polygons through a
// partition into convex polygons.
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::geometry {

using core::Vec2;

/// The penetration depth of two convex regions, each bounded by a closed counter-clockwise loop
/// of segments and convex arcs (world frame): the shortest translation that separates them,
/// min over unit n of h_a(n) + h_b(-n) (h: support function). Computed exactly (up to round-off):
/// between consecutive normal angles of the pieces of both loops, each support is a fixed vertex
/// or arc, so h_a(n) + h_b(-n) = (p - q).n + r_a + r_b, whose minimum over the interval is at an
/// end or at n = -(p - q) / |p - q|. Positive: they overlap by that much; negative: minus their
/// distance; 0: touching.
double convex_penetration_depth(const std::vector<BoundaryPiece>& a,
                                const std::vector<BoundaryPiece>& b);

/// True when the loop turns left (or goes straight) at every joint and along every piece: the
/// region it bounds is convex (the loop is assumed simple and counter-clockwise).
bool is_convex_loop(const std::vector<BoundaryPiece>& loop);

/// Convex polygons (counter-clockwise) whose union is the simple counter-clockwise polygon
/// `vertices` (CGAL's approx_convex_partition_2, Hertel-Mehlhorn); the polygon itself when it is
/// convex.
std::vector<std::vector<Vec2>> convex_partition(const std::vector<Vec2>& vertices);

/// The closed loop of segments through `vertices` (counter-clockwise polygon).
std::vector<BoundaryPiece> polygon_loop(const std::vector<Vec2>& vertices);

/// The overlap depth of two regions given as unions of convex loops: the largest
/// convex_penetration_depth over the pairs of pieces. > 0 exactly when the interiors intersect;
/// for a non-convex region it can be less than the shortest translation that separates the
/// whole regions (a piece's depth, not the union's).
double overlap_depth(const std::vector<std::vector<BoundaryPiece>>& a,
                     const std::vector<std::vector<BoundaryPiece>>& b);

}  // namespace picdem::geometry

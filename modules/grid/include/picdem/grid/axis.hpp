#pragma once
// The axes of the plane, for code written once for both: x (the u samples on the faces normal
// to x, Stagger::FaceX) and z (w, Stagger::FaceZ). A 3D version adds y here; a loop over
// kAxes then covers it without a third copy of the loop body.
#include "picdem/core/vec2.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::grid {

enum class Axis { X, Z };
inline constexpr Axis kAxes[] = {Axis::X, Axis::Z};

/// The staggering of the faces normal to axis a, where a's velocity component lives.
constexpr Stagger face_stagger(Axis a) {
  return a == Axis::X ? Stagger::FaceX : Stagger::FaceZ;
}
/// The unit step along axis a: (di, dk) = (1, 0) for x, (0, 1) for z.
constexpr int step_i(Axis a) {
  return a == Axis::X ? 1 : 0;
}
constexpr int step_k(Axis a) {
  return a == Axis::Z ? 1 : 0;
}
/// The component of v along axis a.
constexpr double component(const core::Vec2& v, Axis a) {
  return a == Axis::X ? v.x : v.z;
}
/// Axis a's member of a pair written out per axis (u or w, E_x or E_z, u_valid or w_valid).
template <class T>
constexpr T& along(Axis a, T& x, T& z) {
  return a == Axis::X ? x : z;
}

}  // namespace picdem::grid

#pragma once
// Open tank sides (issue 16, doc/open_boundaries.md): an inflow with a prescribed inward velocity
// (uniform, parabolic, or a table over the position along the side and time) or an outflow (p = 0
// on the boundary face, do-nothing for the viscous stress), on a range of any of the four sides.
// The rest of a side stays a wall. The keys are open/<side>/... (declare_open_parameters).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::fluid {

enum class OpenKind { Wall, Inflow, Outflow };
enum class InflowShape { Uniform, Parabolic, Table };

/// One tank side (sides in the order left, right, bottom, top: fluid::TankWall). Positions along
/// the side are absolute coordinates: z on the left and right sides, x on the bottom and top.
struct OpenSide {
  OpenKind kind = OpenKind::Wall;
  double from = 0.0, to = 0.0;  ///< the open range along the side [m]; faces whose centre is in it
  InflowShape shape = InflowShape::Uniform;
  double velocity = 0.0;  ///< uniform: the speed; parabolic: the peak (at the range's middle) [m/s]
  /// Table: heights s_m (along the side), times t_l, speeds table[l * heights.size() + m],
  /// bilinear, held constant beyond the first and last entries.
  std::vector<double> heights, times, table;
  /// Outflow: open/<side>/outflow_velocity is zero_gradient: before the projection the outflow
  /// faces take the velocity of the interior faces next to them (du_n / dn = 0), instead of their
  /// own P2G value (projected). p = 0 on the faces either way.
  bool zero_gradient = false;

  /// Whether the face centred at `s` along the side is open.
  bool open_at(double s) const { return kind != OpenKind::Wall && s >= from && s <= to; }
  /// Inward speed [m/s] at `s` and time t (inflow only).
  double speed(double s, double t) const;
  /// Inward displacement of the inflowing fluid since t = 0: the integral of speed(s, t') dt'
  /// over [0, t], exact for every shape (the table is linear in time between its entries).
  double displacement(double s, double t) const;
  /// Lowest and highest displacement(s, t) over s in [s0, s1].
  std::array<double, 2> displacement_bounds(double s0, double s1, double t) const;
};

struct OpenBoundaries {
  std::array<OpenSide, 4> side{};
  double t0 = 0.0, t1 = 0.0;  ///< the step's time interval (set by the step before its phases)

  bool any() const;
  bool any_inflow() const;
  /// The largest speed an inflow side prescribes at time t [m/s] (0 without inflow): bounds the
  /// time step, whose first step from rest the grid's velocities do not yet bound.
  double max_inflow_speed(double t) const;
  /// The inward speed of an inflow face at `s` over the step: (S(t1) - S(t0)) / (t1 - t0), S the
  /// displacement (speed(s, t0) when t1 = t0): the grid carries exactly the injected volume.
  double face_speed(std::size_t side, double s) const;
};

/// Declares open/<side>/type, range, profile, velocity, heights, times, table for the sides
/// left, right, bottom, top, and the checks between them.
void declare_open_parameters(core::ParamSchema& schema);
/// Reads the open/ keys; ranges default to the whole side of `spec`.
OpenBoundaries open_boundaries_from(const core::Params& params, const grid::GridSpec& spec);

/// Position along side `side` of the boundary face with index `f` (0 <= f < nz on the left and
/// right sides, nx on the bottom and top), and the number of faces of the side.
double face_position(const grid::GridSpec& g, std::size_t side, int f);
int side_faces(const grid::GridSpec& g, std::size_t side);

/// Whether the face of cell (i, k) towards its neighbour (ni, nk), a cell outside the grid, is an
/// open face of an outflow side (the pressure rows: p = 0 there).
bool outflow_beyond(const OpenBoundaries& o, const grid::GridSpec& g, int i, int k, int ni, int nk);

}  // namespace picdem::fluid

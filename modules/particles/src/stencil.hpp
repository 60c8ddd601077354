#pragma once
// The 2 x 2 face stencil of a point on the MAC grid (internal to the particles module).
//
// A u sample (FaceX) sits at (x0 + i h, z0 + (k + 1/2) h), a w sample (FaceZ) at
// (x0 + (i + 1/2) h, z0 + k h). The stencil of p is the base face (i, k) with the fractions
// (fx, fz) of p between faces i, i+1 and k, k+1. The base is clamped to faces on the grid, so
// that near a wall the fractions leave [0, 1] (linear extrapolation over half a cell).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles::detail {

struct Stencil {
  int i = 0, k = 0;
  double fx = 0.0, fz = 0.0;
};

/// Where the samples of one staggering sit, in a form that costs no division per particle.
struct Axes {
  double x0 = 0.0, z0 = 0.0;  ///< position of sample (0, 0), in units of h
  double inv_h = 1.0;
  int ni = 0, nk = 0;  ///< samples along x and z
};

inline Axes axes(const grid::GridSpec& spec, grid::Stagger s) {
  Axes a;
  a.inv_h = 1.0 / spec.h;
  // u has its samples at whole x and half z, w the reverse
  a.x0 = spec.origin.x * a.inv_h + (s == grid::Stagger::FaceZ ? 0.5 : 0.0);
  a.z0 = spec.origin.z * a.inv_h + (s == grid::Stagger::FaceX ? 0.5 : 0.0);
  a.ni = spec.nx + (s == grid::Stagger::FaceX ? 1 : 0);
  a.nk = spec.nz + (s == grid::Stagger::FaceZ ? 1 : 0);
  return a;
}

/// floor(v) as an int without a call into libm (the build targets baseline x86-64, which has no
/// rounding instruction): the same value as static_cast<int>(std::floor(v)) for every v in the
/// range of int.
inline int floor_int(double v) {
  const int t = static_cast<int>(v);  // truncates towards zero
  return t - (static_cast<double>(t) > v ? 1 : 0);
}

/// GridSpec::cell_of with the same arithmetic, inline.
inline void cell_of(const grid::GridSpec& s, double x, double z, int& i, int& k) {
  i = floor_int((x - s.origin.x) / s.h);
  k = floor_int((z - s.origin.z) / s.h);
}

inline Stencil stencil(const Axes& a, core::Vec2 p) {
  // sample-index coordinates of p
  const double sx = p.x * a.inv_h - a.x0, sz = p.z * a.inv_h - a.z0;
  Stencil st;
  st.i = std::clamp(floor_int(sx), 0, a.ni - 2);
  st.k = std::clamp(floor_int(sz), 0, a.nk - 2);
  st.fx = sx - st.i;
  st.fz = sz - st.k;
  return st;
}

inline Stencil stencil(const grid::GridSpec& spec, grid::Stagger s, core::Vec2 p) {
  return stencil(axes(spec, s), p);
}

/// The samples at the cell centres (centre of cell (i, k) at (x0 + (i + 1/2) h, z0 + (k + 1/2) h)).
inline Axes cell_axes(const grid::GridSpec& spec) {
  Axes a;
  a.inv_h = 1.0 / spec.h;
  a.x0 = spec.origin.x * a.inv_h + 0.5;
  a.z0 = spec.origin.z * a.inv_h + 0.5;
  a.ni = spec.nx, a.nk = spec.nz;
  return a;
}

/// The stencil of p with its base not clamped to the grid: near a wall it starts on a sample
/// outside the tank and the fractions stay in [0, 1) (the occupancy cuts its tent at the walls
/// instead of extrapolating).
inline Stencil unclamped_stencil(const Axes& a, core::Vec2 p) {
  const double sx = p.x * a.inv_h - a.x0, sz = p.z * a.inv_h - a.z0;
  Stencil st;
  st.i = floor_int(sx);
  st.k = floor_int(sz);
  st.fx = sx - st.i;
  st.fz = sz - st.k;
  return st;
}

/// The stencils of p on the cell centres (unclamped, as unclamped_stencil), the u faces and the w
/// faces (as stencil), with the four sample coordinates and their floors computed once: the
/// centres share their x samples with the w faces and their z samples with the u faces (the same
/// x0, z0). Bitwise the stencils of the separate calls.
inline void three_stencils(const Axes& c, const Axes& u, const Axes& w, core::Vec2 p, Stencil& sc,
                           Stencil& su, Stencil& sw) {
  const double xh = p.x * c.inv_h - c.x0, zh = p.z * c.inv_h - c.z0;  // half-cell lattice
  const double xw = p.x * u.inv_h - u.x0, zw = p.z * w.inv_h - w.z0;  // whole-cell lattice
  const int ih = floor_int(xh), kh = floor_int(zh), iw = floor_int(xw), kw = floor_int(zw);
  sc.i = ih, sc.k = kh, sc.fx = xh - ih, sc.fz = zh - kh;
  su.i = std::clamp(iw, 0, u.ni - 2), su.k = std::clamp(kh, 0, u.nk - 2);
  su.fx = xw - su.i, su.fz = zh - su.k;
  sw.i = std::clamp(ih, 0, w.ni - 2), sw.k = std::clamp(kw, 0, w.nk - 2);
  sw.fx = xh - sw.i, sw.fz = zw - sw.k;
}

/// True when three_stencils gives the separate calls' stencils for these axes (they come from
/// one GridSpec).
inline bool shared_lattice(const Axes& c, const Axes& u, const Axes& w) {
  return c.x0 == w.x0 && c.z0 == u.z0 && c.inv_h == u.inv_h && c.inv_h == w.inv_h;
}

/// Adds one particle's velocity component v and its kernel weights to the four faces of its
/// stencil: m and wt the momentum and weight storage, f the index of the base face, row the
/// storage row length; gx, gz the APIC gradient row times h (0 under FLIP/PIC).
inline void scatter_one(const Stencil& sten, double v, double gx, double gz, double* m, double* wt,
                        std::size_t f, std::size_t row) {
  // kernel clamped to the grid's faces: its centre x_c is p moved onto the outermost row
  const double fx = std::clamp(sten.fx, 0.0, 1.0), fz = std::clamp(sten.fz, 0.0, 1.0);
  // N_f = (1 - |x_f - x_c| / h)(1 - |z_f - z_c| / h)
  const double w00 = (1.0 - fx) * (1.0 - fz), w10 = fx * (1.0 - fz);
  const double w01 = (1.0 - fx) * fz, w11 = fx * fz;
  // APIC: v_f = v_p + C (x_f - x_c); x_f - x_c = ((a - fx) h, (b - fz) h) for face (i+a, k+b)
  const double v00 = v - gx * fx - gz * fz;
  const double v10 = v00 + gx, v01 = v00 + gz, v11 = v00 + gx + gz;
  m[f] += w00 * v00;
  m[f + 1] += w10 * v10;
  m[f + row] += w01 * v01;
  m[f + row + 1] += w11 * v11;
  wt[f] += w00;
  wt[f + 1] += w10;
  wt[f + row] += w01;
  wt[f + row + 1] += w11;
}

/// Makes f a zeroed field of stagger s on d's storage, reusing its memory when it fits.
template <class T>
void reset(grid::GridArray<T>& f, const grid::Decomposition& d, grid::Stagger s) {
  if (f.stagger() == s && f.storage() == d.storage(s) && f.owned() == d.owned(s))
    f.fill(T{});
  else
    f = grid::GridArray<T>(d, s, T{});
}

/// Throws when the stencil reaches outside the field's storage (the particle left the halo).
inline void check_in_storage(const grid::FaceField& f, const Stencil& st, core::Vec2 p) {
  const core::IndexBox& b = f.storage();
  if (st.i >= b.i0 && st.i + 1 < b.i1 && st.k >= b.k0 && st.k + 1 < b.k1) return;
  std::ostringstream m;
  m << "particle at (" << p.x << ", " << p.z << ") is beyond this rank's halo of "
    << "face indices [" << b.i0 << ", " << b.i1 << ") x [" << b.k0 << ", " << b.k1
    << "): it moved more than the halo allows in one step (reduce the time step: |v| dt <= 2 h; "
       "the step is bounded by time/cfl and time/dt_max)";
  throw core::SolverError(m.str());
}

/// Bilinear value of f over the stencil.
inline double interpolate(const grid::FaceField& f, const Stencil& st) {
  const std::size_t n = f.index(st.i, st.k), row = static_cast<std::size_t>(f.storage().nx());
  const double* d = f.data().data();
  // u(p) = (1-fx)(1-fz) u00 + fx (1-fz) u10 + (1-fx) fz u01 + fx fz u11
  return (1.0 - st.fz) * ((1.0 - st.fx) * d[n] + st.fx * d[n + 1]) +
         st.fz * ((1.0 - st.fx) * d[n + row] + st.fx * d[n + row + 1]);
}

/// APIC's G2P: the bilinear value and gradient (d/dx, d/dz) at the kernel centre x_c, the point
/// P2G's kernel is clamped to (scatter_one): p itself away from the walls, p moved onto the
/// outermost row of samples in the half cell next to a wall. P2G rebuilds the field about x_c,
/// v_f = v_p + C (x_f - x_c), so G2P must sample it there too: then P2G after G2P reproduces a
/// bilinear field on every face the particles reach, wall rows included. Sampling the value at p
/// instead extrapolates it, v_p = u(x_c) + C (x_p - x_c), and P2G hands that to the outermost row
/// as if it were u(x_c): a shear across the row grows by up to 1.5 a step (a dam break's front
/// blew up in 150 steps that way). Under FLIP/PIC the value is taken at p (interpolate above).
inline double interpolate_at_centre(const grid::FaceField& f, const Stencil& st, double h,
                                    double& ddx, double& ddz) {
  const std::size_t n = f.index(st.i, st.k), row = static_cast<std::size_t>(f.storage().nx());
  const double* d = f.data().data();
  const double f00 = d[n], f10 = d[n + 1], f01 = d[n + row], f11 = d[n + row + 1];
  const double fx = std::clamp(st.fx, 0.0, 1.0), fz = std::clamp(st.fz, 0.0, 1.0);
  // du/dx = ((1-fz)(u10-u00) + fz (u11-u01)) / h,  du/dz = ((1-fx)(u01-u00) + fx (u11-u10)) / h
  ddx = ((1.0 - fz) * (f10 - f00) + fz * (f11 - f01)) / h;
  ddz = ((1.0 - fx) * (f01 - f00) + fx * (f11 - f10)) / h;
  return (1.0 - fz) * ((1.0 - fx) * f00 + fx * f10) + fz * ((1.0 - fx) * f01 + fx * f11);
}

/// Adds particle n to the count of its cell (GridSpec::cell_of, clamped to the grid); throws when
/// that cell lies beyond the count's storage (count_per_cell).
inline void count_one(const ParticleSet& p, std::size_t n, const grid::GridSpec& s,
                      grid::GridArray<int>& count) {
  int i, k;
  cell_of(s, p.x[n], p.z[n], i, k);
  i = std::clamp(i, 0, s.nx - 1);
  k = std::clamp(k, 0, s.nz - 1);
  if (!count.in_storage(i, k)) {
    std::ostringstream m;
    m << "count_per_cell: particle " << p.id[n] << " at (" << p.x[n] << ", " << p.z[n]
      << ") lies in cell (" << i << ", " << k << ") beyond this rank's halo";
    throw core::SolverError(m.str());
  }
  ++count(i, k);
}

}  // namespace picdem::particles::detail

// The implicit viscous step with the rigid velocities of free bodies as unknowns (viscous.hpp,
// doc/viscous.md "Rigid rows"). Backward Euler for the fluid,
//   (alpha + diag_P) u_P - sum_{interior} u_N = alpha u_old,P + sum_{legs} weight u_B(s) / ...,
// and for each free body b, with s_b = (V_x, V_z, omega) and M_b = diag(m, m, I),
//   M_b (s_b - s_b^n) / dt = F_b(u, s_b)   (the loads of viscous_loads),
// solved by superposition: u(s) = u_0 + sum_j (s_j - s_j^n) g_j, where u_0 is the solve with the
// bodies at s^n and g_j the fluid's answer to a unit rigid velocity j of one body (walls and the
// other bodies at rest, u_old = 0); F is affine in (u, s), so the bodies' equations become the
// dense system (M / dt - K) (s - s^n) = F(u_0, s^n), K_ij = F_i(g_j, e_j). A body with
// rotation_only has omega alone as an unknown: its rows of V_x, V_z are ds = 0 (the split).
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "picdem/core/error.hpp"
#include "picdem/fluid/viscous.hpp"

namespace picdem::fluid {

using core::Vec2;

namespace {

/// The legs' boundary values from the bodies' rigid velocities; the walls' set to 0 (they are
/// at rest in the step: no-slip, or the normal component of free-slip).
void set_leg_values(ViscousStencil& s, const std::vector<ViscousBody>& bodies) {
  for (ViscousLeg& leg : s.legs) {
    if (leg.body < 0) {
      leg.value = 0.0;
      continue;
    }
    const Vec2 v = bodies[static_cast<std::size_t>(leg.body)].velocity_at(leg.point);
    leg.value = s.component == 0 ? v.x : v.z;
  }
}

/// Solves the dense n x n system A x = b (row-major) by Gaussian elimination with partial
/// pivoting.
std::vector<double> solve_dense(std::vector<double> A, std::vector<double> b, std::size_t n) {
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(A[r * n + c]) > std::abs(A[pivot * n + c])) pivot = r;
    if (!(std::abs(A[pivot * n + c]) > 0.0))
      throw core::SolverError("viscous rigid rows: singular body system");
    for (std::size_t k = 0; k < n; ++k) std::swap(A[c * n + k], A[pivot * n + k]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = A[r * n + c] / A[c * n + c];
      for (std::size_t k = c; k < n; ++k) A[r * n + k] -= f * A[c * n + k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double sum = b[r];
    for (std::size_t k = r + 1; k < n; ++k) sum -= A[r * n + k] * x[k];
    x[r] = sum / A[r * n + r];
  }
  return x;
}

/// Body b's unit rigid velocity j (0: V_x, 1: V_z, 2: omega), every other body at rest.
std::vector<ViscousBody> unit_motion(const std::vector<ViscousBody>& bodies, std::size_t b, int j) {
  std::vector<ViscousBody> out = bodies;
  for (auto& body : out) body.velocity = {}, body.omega = 0.0;
  out[b].velocity = {j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0};
  out[b].omega = j == 2 ? 1.0 : 0.0;
  return out;
}

}  // namespace

ViscousLoads solve_viscous_rigid_rows(const ViscousStencil& su, const ViscousStencil& sw, double nu,
                                      double rho, double dt, std::vector<double>& u,
                                      std::vector<double>& w, std::vector<ViscousBody>& bodies,
                                      int& iterations, const ViscousSolverSettings& solver) {
  const double mu = rho * nu;
  std::vector<std::size_t> free;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].mass > 0.0) free.push_back(b);
  const std::size_t n = 3 * free.size();
  const std::vector<double> zero_u(u.size(), 0.0), zero_w(w.size(), 0.0);
  // u_0, w_0: the bodies at s^n
  iterations += solve_viscous_implicit(su, nu, dt, zero_u, u, solver);
  iterations += solve_viscous_implicit(sw, nu, dt, zero_w, w, solver);
  const ViscousLoads base = viscous_loads(su, sw, u, w, mu, bodies);
  std::vector<double> K(n * n, 0.0), rhs(n, 0.0);
  std::vector<std::vector<double>> gu(n), gw(n);
  for (std::size_t f = 0; f < free.size(); ++f)
    for (int j = 0; j < 3; ++j) {
      const std::size_t col = 3 * f + static_cast<std::size_t>(j);
      if (bodies[free[f]].rotation_only && j != 2) {  // its translation stays split: ds = 0
        gu[col] = zero_u, gw[col] = zero_w;
        continue;
      }
      const auto unit = unit_motion(bodies, free[f], j);
      ViscousStencil eu = su, ew = sw;
      set_leg_values(eu, unit);
      set_leg_values(ew, unit);
      gu[col] = zero_u, gw[col] = zero_w;  // u_old = 0: the answer to the legs' values alone
      if (j != 1) iterations += solve_viscous_implicit(eu, nu, dt, zero_u, gu[col], solver);
      if (j != 0) iterations += solve_viscous_implicit(ew, nu, dt, zero_w, gw[col], solver);
      const ViscousLoads l = viscous_loads(eu, ew, gu[col], gw[col], mu, unit);
      for (std::size_t g = 0; g < free.size(); ++g) {
        const std::size_t b = free[g];
        K[(3 * g) * n + col] = l.force[b].x;
        K[(3 * g + 1) * n + col] = l.force[b].z;
        K[(3 * g + 2) * n + col] = l.torque[b];
      }
    }
  // (M / dt - K) ds = F(u_0, s^n)
  for (std::size_t g = 0; g < free.size(); ++g) {
    const ViscousBody& body = bodies[free[g]];
    const double m[3] = {body.mass, body.mass, body.inertia};
    for (std::size_t r = 0; r < 3; ++r) {
      const std::size_t row = 3 * g + r;
      for (std::size_t c = 0; c < n; ++c) K[row * n + c] = -K[row * n + c];
      K[row * n + row] += m[r] / dt;
    }
    rhs[3 * g] = base.force[free[g]].x;
    rhs[3 * g + 1] = base.force[free[g]].z;
    rhs[3 * g + 2] = base.torque[free[g]];
    if (body.rotation_only)  // ds_x = ds_z = 0
      for (std::size_t r = 0; r < 2; ++r) {
        const std::size_t row = 3 * g + r;
        for (std::size_t c = 0; c < n; ++c) K[row * n + c] = c == row ? 1.0 : 0.0;
        rhs[row] = 0.0;
      }
  }
  const std::vector<double> ds = solve_dense(K, rhs, n);
  for (std::size_t col = 0; col < n; ++col) {
    for (std::size_t r = 0; r < u.size(); ++r) u[r] += ds[col] * gu[col][r];
    for (std::size_t r = 0; r < w.size(); ++r) w[r] += ds[col] * gw[col][r];
  }
  for (std::size_t g = 0; g < free.size(); ++g) {
    ViscousBody& body = bodies[free[g]];
    body.velocity += Vec2{ds[3 * g], ds[3 * g + 1]};
    body.omega += ds[3 * g + 2];
  }
  // the loads at the solved state: the bodies at s, the walls as built
  ViscousStencil fu = su, fw = sw;
  for (ViscousStencil* s : {&fu, &fw})
    for (ViscousLeg& leg : s->legs)
      if (leg.body >= 0) {
        const Vec2 v = bodies[static_cast<std::size_t>(leg.body)].velocity_at(leg.point);
        leg.value = s->component == 0 ? v.x : v.z;
      }
  return viscous_loads(fu, fw, u, w, mu, bodies);
}

}  // namespace picdem::fluid

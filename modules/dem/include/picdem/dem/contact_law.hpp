#pragma once
// The spring-dashpot contact law (eqs. 7-15) between two bodies whose closest points are known.
#include "picdem/core/vec2.hpp"
#include "picdem/dem/parameters.hpp"

namespace picdem::dem {

using core::Vec2;

/// Coefficients of one pair (eqs. 10-13) for m_ij = (m_i + m_j) / 2 (m_ij = m_i for a wall).
struct ContactCoefficients {
  double k_n = 0.0, c_n = 0.0, k_t = 0.0, c_t = 0.0;
};
ContactCoefficients coefficients(const DemConfig& cfg, double m_ij);
/// The coefficients per unit m_ij (all four are proportional to m_ij) and their scaling:
/// coefficients(cfg, m) == scaled(unit_coefficients(cfg), m), bit for bit.
ContactCoefficients unit_coefficients(const DemConfig& cfg);
ContactCoefficients scaled(const ContactCoefficients& unit, double m_ij);

/// dt_DEM of eq. 18. With k_xi from eq. 10 it does not depend on the masses:
/// 2 pi / gamma sqrt(m / k) = 2 pi / gamma sqrt(theta h / |g|).
double dem_time_step(const DemConfig& cfg);

/// Rigid-body motion of one side of a contact.
struct BodyMotion {
  Vec2 v;            ///< velocity of the centre of mass
  double omega = 0;  ///< angular velocity
  /// Velocity of the body point at `arm` from the centre of mass.
  Vec2 velocity_at(const Vec2& arm) const { return v + core::cross(omega, arm); }
};

/// Input of one contact evaluation: `point` the contact point (midpoint of the closest points of
/// the real boundaries), `normal` the unit normal from body a towards body b, `delta` the overlap
/// of the imaginary boundaries (eq. 19, > 0), and each body's lever arm: from its centre of mass
/// to its own closest boundary point (R_i n for a circle, as eq. 9).
struct ContactKinematics {
  Vec2 point, normal;
  double delta = 0.0;
  Vec2 arm_a, arm_b;
};

/// Force on body a (body b receives its negative) and the updated tangential spring.
struct ContactForce {
  Vec2 force;
  double spring = 0.0;  ///< accumulated tangential displacement after this evaluation
};

/// Eqs. 7, 8, 15 for body a. `spring` is the accumulated tangential displacement before the
/// step (accumulated model) and `dt` the step of the tangential displacement (dt_DEM, or dt for
/// the predicted loads of the pressure equation).
ContactForce contact_force(const DemConfig& cfg, const ContactCoefficients& k,
                           const ContactKinematics& c, const BodyMotion& a, const BodyMotion& b,
                           double spring, double dt);

}  // namespace picdem::dem

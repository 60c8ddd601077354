#pragma once
// Contact laws as plug-ins (doc/dem.md, "adding a contact law" in doc/architecture.md). A law
// gives the coefficients of a pair from the two masses, the force on body a from the pair's
// kinematics, and the DEM time step it needs. The paper's linear spring-dashpot (eqs. 7-15, 18)
// is the default; contact_law_registry.hpp lists the laws a case file may choose.
#include <limits>
#include <memory>
#include <string>

#include "picdem/core/vec2.hpp"
#include "picdem/dem/parameters.hpp"

namespace picdem::dem {

using core::Vec2;

/// The mass given for the fixed side of a pair (a tank wall or an obstacle).
constexpr double kFixedMass = std::numeric_limits<double>::infinity();

/// The four coefficients of one pair, as its law defines them (for the paper's law eqs. 10-13),
/// and the pair's friction coefficient of eq. 15: dem/mu from the law, replaced by the solver with
/// pair_friction() of the two bodies when the case gives solids their own `friction`.
struct ContactCoefficients {
  double k_n = 0.0, c_n = 0.0, k_t = 0.0, c_t = 0.0;
  double mu = 0.0;
};

/// Friction coefficient of a pair whose bodies have the coefficients mu_a and mu_b (a tank wall or
/// an obstacle has dem/mu): the smaller, as Yade's default for two frictional materials (the
/// smaller friction angle; doc/dem.md, "Friction by population").
inline double pair_friction(double mu_a, double mu_b) {
  return mu_a < mu_b ? mu_a : mu_b;
}

/// Rigid-body motion of one side of a contact.
struct BodyMotion {
  Vec2 v;                       ///< velocity of the centre of mass
  double omega = 0;             ///< angular velocity
  double inertia = kFixedMass;  ///< moment of inertia (infinite: a wall or an obstacle)
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
  double torque = 0.0;  ///< rolling-resistance torque on body a (body b receives its negative)
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  /// The value of dem/contact_law that chooses this law.
  virtual std::string name() const = 0;
  /// Coefficients of a pair of bodies of masses m_a and m_b (m_b = kFixedMass for a tank wall or
  /// an obstacle), computed once per pair evaluation and handed back to force().
  virtual ContactCoefficients coefficients(double m_a, double m_b) const = 0;
  /// Force on body a. `spring` is the accumulated tangential displacement before the step
  /// (accumulated model) and `dt` the step of the tangential displacement (dt_DEM, or dt for the
  /// predicted loads of the pressure equation).
  virtual ContactForce force(const ContactCoefficients& k, const ContactKinematics& c,
                             const BodyMotion& a, const BodyMotion& b, double spring,
                             double dt) const = 0;
  /// dt_DEM this law needs when the solids' masses lie in [m_min, m_max] (0, 0 before any solid
  /// is known).
  virtual double time_step(double m_min, double m_max) const = 0;
  /// The law as it applies to a case whose solids' masses lie in [m_min, m_max] (the same on
  /// every rank); DemSolver uses it once the solids are known. A law whose coefficients depend
  /// on the pair alone returns a copy of itself.
  virtual std::shared_ptr<const ContactLaw> for_masses(double m_min, double m_max) const = 0;
};

using ContactLawPtr = std::shared_ptr<const ContactLaw>;

// ---- the paper's linear spring-dashpot (contact_law.cpp) --------------------------------------

/// Coefficients of one pair (eqs. 10-13) for m_ij = (m_i + m_j) / 2 (m_ij = m_i for a wall), with
/// mu = cfg.mu.
ContactCoefficients coefficients(const DemConfig& cfg, double m_ij);
/// The coefficients per unit m_ij (all four are proportional to m_ij; mu is kept) and their
/// scaling: coefficients(cfg, m) == scaled(unit_coefficients(cfg), m), bit for bit.
ContactCoefficients unit_coefficients(const DemConfig& cfg);
ContactCoefficients scaled(const ContactCoefficients& unit, double m_ij);

/// dt_DEM of eq. 18. With k_xi from eq. 10 it does not depend on the masses:
/// 2 pi / gamma sqrt(m / k) = 2 pi / gamma sqrt(theta h / |g|).
double dem_time_step(const DemConfig& cfg);

/// The share of the damped stability limit that damped_step_limit takes: a body with several
/// contacts has faster modes than one pair (doc/dem.md, "Damped time step").
constexpr double kDampedStepShare = 0.25;

/// The largest stable dt_DEM of eqs. 21-24 for the damped spring of the case's lightest pair of
/// solids, normal and tangential-rotational modes of disks, when the heaviest solid is
/// `mass_ratio` times as heavy, times kDampedStepShare (doc/dem.md, "Damped time step"). The
/// paper's law takes the smaller of it and eq. 18; at the default alpha eq. 18 is smaller.
double damped_step_limit(const DemConfig& cfg, double mass_ratio);

/// Eqs. 7, 8, 15 for body a (see ContactLaw::force).
ContactForce contact_force(const DemConfig& cfg, const ContactCoefficients& k,
                           const ContactKinematics& c, const BodyMotion& a, const BodyMotion& b,
                           double spring, double dt);

/// Rolling resistance on body a (doc/dem.md, "Rolling resistance"): the constant directional
/// torque -mu_r R* |F_n| sign(omega_a - omega_b), R* = R_a R_b / (R_a + R_b) from the lever arms
/// (R_a at a wall), capped by the torque that stops the relative rotation within `dt`, so it never
/// reverses it. 0 when mu_r = 0.
double rolling_torque(double mu_r, double F_n, const ContactKinematics& c, const BodyMotion& a,
                      const BodyMotion& b, double dt);

/// The paper's law as a ContactLaw, from cfg's alpha, psi, mu, theta, gamma, h, g_stiffness and
/// tangential model ("linear_spring_dashpot").
ContactLawPtr linear_spring_dashpot(const DemConfig& cfg);

// ---- Hertz-Mindlin (hertz_mindlin.cpp) --------------------------------------------------------

/// F_n = k_hz delta^{3/2} + c_hz delta^{1/4} d(delta)/dt with k_hz = m_ij |g| / (theta h)^{3/2}
/// and c_hz = a(e) sqrt(m* k_hz) for the normal restitution e (exact for any impact speed),
/// Mindlin's tangential spring k_t = kappa dF_n/d(delta), Coulomb-capped ("hertz_mindlin"; the
/// formulas, their sources and the time step in doc/dem.md). Uses cfg's psi, mu, theta, gamma, h,
/// g_stiffness, gap and tangential model.
ContactLawPtr hertz_mindlin(const DemConfig& cfg, double restitution);

/// The damping factor a(e) = sqrt(5) (-ln e) / sqrt(pi^2 + ln^2 e) of the Hertz law.
double hertz_damping_factor(double restitution);

}  // namespace picdem::dem

// The paper's linear spring-dashpot (eqs. 7-15, 18) and its registration as the default law.
#include <algorithm>
#include <cmath>

#include "picdem/dem/contact_law.hpp"
#include "picdem/dem/contact_law_registry.hpp"

namespace picdem::dem {

ContactCoefficients unit_coefficients(const DemConfig& cfg) {
  // every coefficient is m_ij times a constant of the case
  const double k1 = cfg.g_stiffness / (cfg.theta * cfg.h);
  ContactCoefficients u;
  // eq. 10: k_xi = m_ij ||g|| / (theta dx)
  u.k_n = k1;
  // eq. 11: c_xi = 2 alpha sqrt(m_ij k_xi) = 2 alpha m_ij sqrt(||g|| / (theta dx))
  u.c_n = 2.0 * cfg.alpha * std::sqrt(k1);
  // eq. 12: k_eta = k_xi / (2 (1 + psi))
  u.k_t = k1 / (2.0 * (1.0 + cfg.psi));
  // eq. 13: c_eta = c_xi / sqrt(2 (1 + psi))
  u.c_t = u.c_n / std::sqrt(2.0 * (1.0 + cfg.psi));
  // eq. 15's mu, not scaled
  u.mu = cfg.mu;
  return u;
}

ContactCoefficients scaled(const ContactCoefficients& unit, double m_ij) {
  return {m_ij * unit.k_n, m_ij * unit.c_n, m_ij * unit.k_t, m_ij * unit.c_t, unit.mu};
}

ContactCoefficients coefficients(const DemConfig& cfg, double m_ij) {
  return scaled(unit_coefficients(cfg), m_ij);
}

double dem_time_step(const DemConfig& cfg) {
  // eq. 18 with eq. 10: dt_DEM = 2 pi / gamma sqrt(m_ij / k_xi) = 2 pi / gamma sqrt(theta dx /
  // ||g||)
  return 2.0 * 3.141592653589793 / cfg.gamma * std::sqrt(cfg.theta * cfg.h / cfg.g_stiffness);
}

double damped_step_limit(const DemConfig& cfg, double mass_ratio) {
  // the lightest pair of the case, two solids of m_min (m* = m_min / 2) under k_xi = m_max ||g||
  // / (theta dx): omega_n^2 = k_xi / m* = 2 (m_max / m_min) ||g|| / (theta dx), zeta_n =
  // c_xi / (2 sqrt(m* k_xi)) = sqrt(2) alpha (the paper's equal pair; a wall pair is slower and
  // less damped). Its tangential mode with the disks' rotation (|b_t|^2 = 3 |b_n|^2 for
  // I = m R^2 / 2): omega_t = omega_n sqrt(3 / (2 (1 + psi))), zeta_t = sqrt(3) zeta_n.
  const double w_n = std::sqrt(2.0 * mass_ratio * cfg.g_stiffness / (cfg.theta * cfg.h));
  const double z_n = std::sqrt(2.0) * cfg.alpha;
  const double w_t = w_n * std::sqrt(3.0 / (2.0 * (1.0 + cfg.psi))), z_t = std::sqrt(3.0) * z_n;
  // eqs. 21-24 on x'' = -omega^2 x - 2 zeta omega x' are stable for
  // omega dt < 2 (sqrt(1 + zeta^2) - zeta) = 2 / (sqrt(1 + zeta^2) + zeta) (doc/dem.md, "Damped
  // time step"; the second form does not cancel at large zeta)
  const auto limit = [](double w, double z) { return 2.0 / ((std::hypot(1.0, z) + z) * w); };
  return kDampedStepShare * std::min(limit(w_n, z_n), limit(w_t, z_t));
}

ContactForce contact_force(const DemConfig& cfg, const ContactCoefficients& k,
                           const ContactKinematics& c, const BodyMotion& a, const BodyMotion& b,
                           double spring, double dt) {
  const Vec2 n = c.normal, t = core::perp(n);
  // relative velocity of b with respect to a at the contact point
  const Vec2 U = b.velocity_at(c.arm_b) - a.velocity_at(c.arm_a);
  const double U_n = core::dot(U, n), U_t = core::dot(U, t);
  // eq. 7: F_xi = k_xi delta + c_xi U_xi, U_xi the approach speed -U_n (repulsive when > 0)
  const double F_n = k.k_n * c.delta - k.c_n * U_n;
  // eq. 8: F_eta = k_eta (U_eta dt_DEM) + c_eta U_eta; accumulated: the spring holds sum U_eta dt
  double s = (cfg.tangential == TangentialModel::Accumulated ? spring : 0.0) + U_t * dt;
  double F_t = k.k_t * s + k.c_t * U_t;
  // eq. 15: |F_eta| <= mu |F_xi| (mu of the pair); the accumulated spring slips to the cap
  const double cap = k.mu * std::abs(F_n);
  if (std::abs(F_t) > cap) {
    F_t = std::copysign(cap, F_t);
    s = F_t / k.k_t;
  }
  ContactForce out;
  out.force = -F_n * n + F_t * t;
  out.spring = cfg.tangential == TangentialModel::Accumulated ? s : 0.0;
  out.torque = rolling_torque(cfg.mu_r, F_n, c, a, b, dt);
  return out;
}

double rolling_torque(double mu_r, double F_n, const ContactKinematics& c, const BodyMotion& a,
                      const BodyMotion& b, double dt) {
  const double w = a.omega - b.omega;  // relative rolling
  if (mu_r == 0.0 || w == 0.0) return 0.0;
  const bool fixed = b.inertia == kFixedMass;
  const double ra = core::norm(c.arm_a), rb = core::norm(c.arm_b);
  const double R = fixed ? ra : ra * rb / (ra + rb);
  // the torque that stops the relative rotation in one step: the cap that keeps the constant
  // torque from reversing omega_rel (and from adding energy) as omega_rel -> 0
  const double inv_I = 1.0 / a.inertia + (fixed ? 0.0 : 1.0 / b.inertia);
  const double stop = std::abs(w) / (inv_I * dt);
  // M_r = -mu_r R* |F_n| sign(omega_rel)
  return -std::copysign(std::min(mu_r * R * std::abs(F_n), stop), w);
}

namespace {

class LinearSpringDashpot final : public ContactLaw {
 public:
  /// m_s > 0: the stiffness mass of a case (for_masses), 0: each pair's own m_ij (the paper's).
  LinearSpringDashpot(const DemConfig& cfg, double m_s)
      : cfg_(cfg), unit_(unit_coefficients(cfg)), dt_(dem_time_step(cfg)), m_s_(m_s) {
    cfg_.contact_law = nullptr;  // the law keeps the settings, not itself
  }
  std::string name() const override { return "linear_spring_dashpot"; }

  ContactCoefficients coefficients(double m_a, double m_b) const override {
    const bool fixed = m_b == kFixedMass;
    // eqs. 10-13 with m_ij = m_i against a wall or an obstacle, (m_i + m_j) / 2 for two solids
    const double m_ij = fixed ? m_a : 0.5 * (m_a + m_b);
    if (m_s_ == 0.0 || (m_ij == m_s_ && (fixed || m_a == m_b))) return scaled(unit_, m_ij);
    // any mass ratio (doc/dem.md, "Unequal masses"): k = m_s ||g|| / (theta dx) for every pair,
    // c = 2 alpha sqrt(m_d k) with m_d = m_i at a wall, 2 m* = 2 m_i m_j / (m_i + m_j) between
    // solids: the paper's damping ratio for every pair
    const double m_d = fixed ? m_a : 2.0 * m_a * m_b / (m_a + m_b);
    ContactCoefficients k = scaled(unit_, m_s_);
    const double c = std::sqrt(m_d / m_s_);
    k.c_n *= c;
    k.c_t *= c;
    return k;
  }

  ContactForce force(const ContactCoefficients& k, const ContactKinematics& c, const BodyMotion& a,
                     const BodyMotion& b, double spring, double dt) const override {
    return contact_force(cfg_, k, c, a, b, spring, dt);
  }

  double time_step(double m_min, double m_max) const override {
    // eq. 18 for the pair that needs the smallest step, the two lightest solids (or the lightest
    // at a wall) under k = m_max ||g|| / (theta dx): dt_paper sqrt(m_min / m_max)
    const bool equal = !(m_min > 0.0) || m_min == m_max;
    const double paper = equal ? dt_ : dt_ * std::sqrt(m_min / m_max);
    const double ratio = equal ? 1.0 : m_max / m_min;
    // eq. 18 ignores the dashpot: the smaller of it and the damped limit (doc/dem.md)
    return std::min(paper, damped_step_limit(cfg_, ratio));
  }

  ContactLawPtr for_masses(double, double m_max) const override {
    return std::make_shared<LinearSpringDashpot>(cfg_, m_max);
  }

 private:
  DemConfig cfg_;
  ContactCoefficients unit_;  // eqs. 10-13 per unit m_ij
  double dt_;                 // eq. 18
  double m_s_;                // stiffness mass; 0: the pair's m_ij
};

}  // namespace

ContactLawPtr linear_spring_dashpot(const DemConfig& cfg) {
  return std::make_shared<LinearSpringDashpot>(cfg, 0.0);
}

ContactLawType linear_spring_dashpot_type() {
  ContactLawType t;
  t.name = "linear_spring_dashpot";
  t.doc = "the paper's linear spring-dashpot (eqs. 7-15, 18)";
  t.declare = [](core::ParamSchema& s) {
    s.real("dem/alpha", 0.4, "damping tuning parameter alpha (eq. 11; linear_spring_dashpot)")
        .non_negative();
  };
  t.build = [](const core::Params&, const DemConfig& cfg) { return linear_spring_dashpot(cfg); };
  return t;
}

}  // namespace picdem::dem

// Hertz-Mindlin: a nonlinear normal spring F = k_hz delta^{3/2} with the damping that gives a
// chosen normal restitution for any impact speed, and Mindlin's tangential spring, Coulomb-capped
// (doc/dem.md, "Hertz-Mindlin").
#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/dem/contact_law.hpp"
#include "picdem/dem/contact_law_registry.hpp"

namespace picdem::dem {

namespace {

constexpr double kPi = 3.141592653589793;

class HertzMindlin final : public ContactLaw {
 public:
  /// m_s > 0: the stiffness mass of a case (for_masses), 0: each pair's own m_ij.
  HertzMindlin(const DemConfig& cfg, double restitution, double m_s = 0.0)
      : m_s_(m_s),
        mu_(cfg.mu),
        mu_r_(cfg.mu_r),
        gamma_(cfg.gamma),
        g_(cfg.g_stiffness),
        accumulated_(cfg.tangential == TangentialModel::Accumulated) {
    if (!(restitution > 0.0 && restitution <= 1.0)) {
      std::ostringstream m;
      m << "dem/hertz_mindlin/restitution = " << restitution << "; allowed: in (0, 1]";
      throw core::InputError(m.str());
    }
    delta_ref_ = cfg.theta * cfg.h;
    // the weight m_ij |g| compresses the spring by theta dx, as eq. 10 for the linear law
    k1_ = g_ / (delta_ref_ * std::sqrt(delta_ref_));
    a_ = hertz_damping_factor(restitution);
    // Mindlin: tangential over normal stiffness for two bodies of one material
    kappa_ = 2.0 * (1.0 - cfg.psi) / (2.0 - cfg.psi);
    // the overlap the time step resolves: where the real boundaries touch (at least theta dx)
    delta_dt_ = std::max(cfg.gap(), delta_ref_);
  }

  std::string name() const override { return "hertz_mindlin"; }

  ContactCoefficients coefficients(double m_a, double m_b) const override {
    const bool fixed = m_b == kFixedMass;
    const double m_ij = fixed ? m_a : 0.5 * (m_a + m_b);
    const double m_star = fixed ? m_a : m_a * m_b / (m_a + m_b);
    ContactCoefficients k;
    // k_hz = m |g| / (theta dx)^{3/2}: m = m_ij of the pair, or the case's largest mass m_s for
    // every pair (doc/dem.md, "Unequal masses"; equal masses: m_s = m_ij, the same bits)
    k.k_n = (m_s_ > 0.0 ? m_s_ : m_ij) * k1_;  // k_hz
    k.c_n = a_ * std::sqrt(m_star * k.k_n);    // c_hz = a(e) sqrt(m* k_hz)
    k.k_t = kappa_ * 1.5 * k.k_n;              // k_t = kappa dF_n/d(delta) / sqrt(delta)
    k.c_t = std::sqrt(kappa_) * k.c_n;         // c_t = sqrt(kappa) c_hz
    k.mu = mu_;
    return k;
  }

  ContactForce force(const ContactCoefficients& k, const ContactKinematics& c, const BodyMotion& a,
                     const BodyMotion& b, double spring, double dt) const override {
    const Vec2 n = c.normal, t = core::perp(n);
    // relative velocity of b with respect to a at the contact point; approach: U_n < 0
    const Vec2 U = b.velocity_at(c.arm_b) - a.velocity_at(c.arm_a);
    const double U_n = core::dot(U, n), U_t = core::dot(U, t);
    const double sd = std::sqrt(c.delta), qd = std::sqrt(sd);  // delta^{1/2}, delta^{1/4}
    // F_n = k_hz delta^{3/2} + c_hz delta^{1/4} d(delta)/dt, d(delta)/dt = -U_n
    const double F_n = k.k_n * c.delta * sd - k.c_n * qd * U_n;
    // F_t = k_t delta^{1/2} s + c_t delta^{1/4} U_t, s the tangential displacement (eq. 8's)
    const double kt = k.k_t * sd, ct = k.c_t * qd;
    double s = (accumulated_ ? spring : 0.0) + U_t * dt;
    double F_t = kt * s + ct * U_t;
    // eq. 15: |F_t| <= mu |F_n| (mu of the pair); the accumulated spring slips to the cap
    const double cap = k.mu * std::abs(F_n);
    if (std::abs(F_t) > cap) {
      F_t = std::copysign(cap, F_t);
      s = F_t / kt;
    }
    ContactForce out;
    out.force = -F_n * n + F_t * t;
    out.spring = accumulated_ ? s : 0.0;
    out.torque = rolling_torque(mu_r_, F_n, c, a, b, dt);
    return out;
  }

  ContactLawPtr for_masses(double, double m_max) const override {
    auto law = std::make_shared<HertzMindlin>(*this);
    law->m_s_ = m_max;
    return law;
  }

  double time_step(double m_min, double m_max) const override {
    // q = m* / m of the pair that needs the smallest step, m its stiffness mass. Pair's m_ij:
    // the most unequal pair, 2 r / (1 + r)^2 with r = m_max / m_min (1/2 for equal masses; a
    // wall's 1 is larger). Case-wide m_s = m_max: the two lightest solids, m* = m_min / 2, so
    // q = m_min / (2 m_max) (1/2 for equal masses, as the pair's rule)
    const double r = m_min > 0.0 ? m_max / m_min : 1.0;
    const double q =
        m_s_ > 0.0 && m_min > 0.0 ? 0.5 * (m_min / m_max) : 2.0 * r / ((1.0 + r) * (1.0 + r));
    // T = 2 pi sqrt(m* / S), S = dF_n/d(delta) = 1.5 k_hz delta^{1/2} at delta_dt; dt = T / gamma
    const double S_per_m = 1.5 * k1_ * std::sqrt(delta_dt_);
    return 2.0 * kPi / gamma_ * std::sqrt(q / S_per_m);
  }

 private:
  double m_s_;  // stiffness mass; 0: the pair's m_ij
  double mu_, mu_r_, gamma_, g_;
  bool accumulated_;
  double delta_ref_ = 0.0, k1_ = 0.0, a_ = 0.0, kappa_ = 0.0, delta_dt_ = 0.0;
};

}  // namespace

double hertz_damping_factor(double e) {
  // Antypov & Elliott (2011), Feng (2026): the phase-space path of the damped Hertz spring is that
  // of a linear spring-dashpot of damping ratio a / sqrt(5), whose restitution is
  // exp(-zeta pi / sqrt(1 - zeta^2)); solved for a.
  const double l = std::log(e);
  return std::sqrt(5.0) * (-l) / std::sqrt(kPi * kPi + l * l);
}

ContactLawPtr hertz_mindlin(const DemConfig& cfg, double restitution) {
  return std::make_shared<HertzMindlin>(cfg, restitution);
}

ContactLawType hertz_mindlin_type() {
  ContactLawType t;
  t.name = "hertz_mindlin";
  t.doc =
      "Hertz normal spring delta^{3/2} with a damping for a chosen restitution, Mindlin's "
      "tangential spring, Coulomb cap";
  t.declare = [](core::ParamSchema& s) {
    s.real("dem/hertz_mindlin/restitution", 0.5,
           "normal coefficient of restitution e of a binary collision (hertz_mindlin), any speed")
        .greater_than(0.0)
        .at_most(1.0);
  };
  t.build = [](const core::Params& p, const DemConfig& cfg) {
    return hertz_mindlin(cfg, p.real("dem/hertz_mindlin/restitution"));
  };
  return t;
}

}  // namespace picdem::dem

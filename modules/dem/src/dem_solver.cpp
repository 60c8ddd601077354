#include "picdem/dem/dem_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "picdem/dem/contact_geometry.hpp"

namespace picdem::dem {

using core::SolidLoads;
using core::SolidState;
using geometry::Segment;

namespace {

BodyMotion motion_of(const SolidState& s) {
  return {s.v, s.omega, s.inertia};
}

geometry::Pose pose_of(const SolidState& s) {
  return {s.x, s.theta};
}

constexpr std::int64_t wall_key(int side) {
  return -1 - side;
}
constexpr std::int64_t obstacle_key(std::size_t k) {
  return -5 - static_cast<std::int64_t>(k);
}

double spring_of(const std::vector<std::pair<std::int64_t, double>>& springs, std::int64_t key) {
  for (const auto& [k, s] : springs)
    if (k == key) return s;
  return 0.0;
}

/// Outward normal of tank side 0 left, 1 right, 2 bottom, 3 top.
Vec2 wall_normal(int side) {
  static const Vec2 n[4] = {{-1.0, 0.0}, {1.0, 0.0}, {0.0, -1.0}, {0.0, 1.0}};
  return n[side];
}

/// Step (1) of eqs. 21-25: U_0 = U^n + (M^-1 F_fluid + g) dt, X_0 = X^n; keeps U^n in v_start,
/// omega_start. `fluid_loads` in any order, any subset of the solids.
void kick(std::vector<SolidLoads> loads, const Vec2 gravity, double dt,
          std::vector<SolidState>& owned, std::vector<Vec2>& v_start,
          std::vector<double>& omega_start) {
  std::sort(loads.begin(), loads.end(),
            [](const SolidLoads& a, const SolidLoads& b) { return a.id < b.id; });
  for (std::size_t i = 0; i < owned.size(); ++i) {
    SolidState& s = owned[i];
    v_start[i] = s.v;
    omega_start[i] = s.omega;
    Vec2 F{};
    double T = 0.0;
    auto it = std::lower_bound(loads.begin(), loads.end(), s.id,
                               [](const SolidLoads& l, std::int64_t v) { return l.id < v; });
    if (it != loads.end() && it->id == s.id) F = it->force, T = it->torque;
    s.v += (F / s.mass + gravity) * dt;
    s.omega += T / s.inertia * dt;
  }
}

/// Eqs. 22 and 24: X = X_{k-1} + (v0 + U) / 2 dt_DEM, v0 = U^n (paper) or U_{k-1}.
void step_position(SolidState& s, const SolidState& p, const Vec2 v0, double w0, double h) {
  s.x = p.x + (0.5 * h) * (v0 + s.v);
  s.theta = p.theta + 0.5 * h * (w0 + s.omega);
}

}  // namespace

DemSolver::DemSolver(core::Comm comm, DemConfig config, std::vector<core::Box2> regions,
                     core::Box2 tank, std::vector<std::vector<core::Vec2>> obstacle_polygons)
    : comm_(comm), cfg_(config), regions_(std::move(regions)), tank_(tank) {
  if (static_cast<int>(regions_.size()) != comm_.size()) {
    std::ostringstream m;
    m << "DemSolver: " << regions_.size() << " regions given for " << comm_.size()
      << " ranks; allowed: one region per rank";
    throw core::InputError(m.str());
  }
  if (!(cfg_.h > 0.0)) {
    std::ostringstream m;
    m << "DemSolver: cell size h = " << cfg_.h << "; allowed: > 0";
    throw core::InputError(m.str());
  }
  for (const auto& poly : obstacle_polygons) {
    if (poly.size() < 3)
      throw core::InputError("DemSolver: an obstacle polygon has fewer than 3 vertices");
    std::vector<geometry::BoundaryPiece> pieces;
    core::Box2 box{poly.front(), poly.front()};
    for (std::size_t v = 0; v < poly.size(); ++v) {
      pieces.emplace_back(Segment{poly[v], poly[(v + 1) % poly.size()]});
      box.lo = {std::min(box.lo.x, poly[v].x), std::min(box.lo.z, poly[v].z)};
      box.hi = {std::max(box.hi.x, poly[v].x), std::max(box.hi.z, poly[v].z)};
    }
    obstacles_.push_back(with_ends(std::move(pieces)));
    obstacle_boxes_.push_back(box);
  }
  law_ = cfg_.contact_law ? cfg_.contact_law : linear_spring_dashpot(cfg_);
  dt_dem_ = law_->time_step(0.0, 0.0);
  send_list_.resize(static_cast<std::size_t>(comm_.size()));
  recv_count_.assign(static_cast<std::size_t>(comm_.size()), 0);
}

const DemSolver::Statics& DemSolver::statics_of(std::int64_t id) const {
  auto it = std::lower_bound(statics_.begin(), statics_.end(), id,
                             [](const Statics& s, std::int64_t v) { return s.id < v; });
  if (it == statics_.end() || it->id != id) {
    std::ostringstream m;
    m << "DemSolver: no solid with id " << id;
    throw core::InputError(m.str());
  }
  return *it;
}

double DemSolver::friction_of(std::int64_t id) const {
  const auto n = static_cast<std::size_t>(id);
  if (id >= 0 && n < statics_.size() && statics_[n].id == id) return statics_[n].mu;
  return statics_of(id).mu;
}

geometry::ShapePtr DemSolver::shape_of(std::int64_t id) const {
  return shapes_[static_cast<std::size_t>(statics_of(id).shape)].shape;
}

void DemSolver::add_solids(const std::vector<SolidSpec>& solids) {
  for (const auto& spec : solids) {
    if (!spec.shape) throw core::InputError("DemSolver::add_solids: a solid has no shape");
    if (!(spec.density > 0.0)) {
      std::ostringstream m;
      m << "solid " << spec.state.id << ": density = " << spec.density << "; allowed: > 0";
      throw core::InputError(m.str());
    }
    // one entry per distinct shape; a map, as a graded packing gives each solid its own shape
    const auto found = shape_index_.find(spec.shape.get());
    int index = found == shape_index_.end() ? -1 : found->second;
    if (index < 0) {
      ShapeInfo info;
      info.shape = spec.shape;
      info.body = with_ends(spec.shape->boundary());
      // the shape's declared fast path: a centred circle takes eq. 19 in closed form
      info.circle = spec.shape->fast_paths().centred_circle_radius > 0.0;
      info.radius = spec.shape->bounding_radius();
      index = static_cast<int>(shapes_.size());
      shapes_.push_back(std::move(info));
      shape_index_[spec.shape.get()] = index;
    }
    const auto mp = spec.shape->mass_properties();
    SolidState s = spec.state;
    s.shape = index;
    s.mass = spec.density * mp.area;
    s.inertia = spec.density * mp.polar_moment;
    // a solid without its own friction has the case's dem/mu
    own_friction_ = own_friction_ || spec.friction >= 0.0;
    statics_.push_back(
        {s.id, index, s.mass, s.inertia, spec.friction >= 0.0 ? spec.friction : cfg_.mu});
    max_radius_ = std::max(max_radius_, shapes_[static_cast<std::size_t>(index)].radius);
    if (owner_of(s.x) == comm_.rank()) {
      owned_.push_back(s);
      springs_.emplace_back();
      v_start_.push_back(s.v);
      omega_start_.push_back(s.omega);
    }
  }
  std::sort(statics_.begin(), statics_.end(),
            [](const Statics& a, const Statics& b) { return a.id < b.id; });
  for (std::size_t n = 1; n < statics_.size(); ++n)
    if (statics_[n].id == statics_[n - 1].id) {
      std::ostringstream m;
      m << "DemSolver::add_solids: solid id " << statics_[n].id
        << " given twice; allowed: unique ids";
      throw core::InputError(m.str());
    }
  skin_ = cfg_.skin > 0.0 ? cfg_.skin : 0.2 * max_radius_;
  // the time step the law needs for the masses of the case (every solid, the same on all ranks)
  double m_min = statics_.empty() ? 0.0 : statics_.front().mass, m_max = m_min;
  for (const auto& st : statics_)
    m_min = std::min(m_min, st.mass), m_max = std::max(m_max, st.mass);
  law_ =
      (cfg_.contact_law ? cfg_.contact_law : linear_spring_dashpot(cfg_))->for_masses(m_min, m_max);
  dt_dem_ = law_->time_step(m_min, m_max);
  mass_range_ = {m_min, m_max};
  sort_owned();
  rebuild();
}

// ---------------------------------------------------------------------------------------------
// contact geometry of the three kinds of pairs

bool DemSolver::solid_pair(const SolidState& a, const SolidState& b, ContactKinematics& k) const {
  const ShapeInfo& sa = shapes_[static_cast<std::size_t>(a.shape)];
  const ShapeInfo& sb = shapes_[static_cast<std::size_t>(b.shape)];
  const double gap = cfg_.gap();
  const Vec2 c = b.x - a.x;
  const double reach = sa.radius + sb.radius + gap, d2 = core::norm2(c);
  if (d2 >= reach * reach) return false;
  const double d = std::sqrt(d2);
  if (sa.circle && sb.circle) {
    // eq. 19: delta = r_i + r_j + 2 dx - d_ij
    const double delta = sa.radius + sb.radius + gap - d;
    if (delta <= 0.0 || d == 0.0) return false;
    k.normal = c / d;
    const Vec2 on_a = a.x + sa.radius * k.normal, on_b = b.x - sb.radius * k.normal;
    k.point = 0.5 * (on_a + on_b);
    k.delta = delta;
    // eq. 9: the lever arm is the radius
    k.arm_a = sa.radius * k.normal;
    k.arm_b = -sb.radius * k.normal;
    return true;
  }
  // only the pieces of each boundary that can reach the other body
  auto& wa = scratch_a_;
  auto& wb = scratch_b_;
  wa.clear();
  wb.clear();
  to_world_near(sa.body, pose_of(a), b.x, sb.radius + gap, wa);
  to_world_near(sb.body, pose_of(b), a.x, sa.radius + gap, wb);
  if (wa.pieces.empty() || wb.pieces.empty()) return false;
  const ClosestPoints cp = closest_points(wa, wb);
  // eq. 19 for any shapes: delta = 2 dx - distance between the real boundaries
  const double delta = gap - cp.distance;
  if (delta <= 0.0) return false;
  if (cp.distance > 1e-12 * (sa.radius + sb.radius))
    k.normal = (cp.on_b - cp.on_a) / cp.distance;
  else if (d > 0.0)
    k.normal = c / d;
  else
    return false;
  Vec2 on_a, on_b;
  face_weighted(cp, gap, on_a, on_b);
  k.point = 0.5 * (on_a + on_b);
  k.delta = delta;
  k.arm_a = on_a - a.x;
  k.arm_b = on_b - b.x;
  return true;
}

bool DemSolver::wall_pair(const SolidState& a, int side, ContactKinematics& k) const {
  const ShapeInfo& sa = shapes_[static_cast<std::size_t>(a.shape)];
  const Vec2 n = wall_normal(side);
  // distance of the centre to the wall along the outward normal
  const double wall = side == 0   ? -tank_.lo.x
                      : side == 1 ? tank_.hi.x
                      : side == 2 ? -tank_.lo.z
                                  : tank_.hi.z;
  const double centre_gap = wall - core::dot(a.x, n);
  const double gap = cfg_.gap();
  if (centre_gap - sa.radius >= gap) return false;
  if (sa.circle) {
    // eq. 19 against a wall: delta = r_i + 2 dx - d_iw
    const double delta = sa.radius + gap - centre_gap;
    if (delta <= 0.0) return false;
    const double dist = centre_gap - sa.radius;
    k.normal = n;
    k.point = a.x + (sa.radius + 0.5 * dist) * n;
    k.delta = delta;
    k.arm_a = sa.radius * n;
    return true;
  }
  auto& wa = scratch_a_;
  to_world(sa.body, pose_of(a), wa);
  const Vec2 deepest = support_point(wa, n);
  const double dist = wall - core::dot(deepest, n);
  const double delta = gap - dist;
  if (delta <= 0.0) return false;
  // the wall as a long segment along the tank side: a flat face gets its middle as contact point
  const Vec2 t = core::perp(n);
  const Vec2 foot = deepest + dist * n;
  const double L = 4.0 * sa.radius + 1.0;
  const ClosestPoints cp = closest_points(wa, with_ends({Segment{foot - L * t, foot + L * t}}));
  Vec2 on_a = deepest, on_wall;
  if (cp.face && cp.distance > 0.0) face_weighted(cp, gap, on_a, on_wall);
  k.normal = n;
  k.point = on_a + 0.5 * dist * n;
  k.delta = delta;
  k.arm_a = on_a - a.x;
  return true;
}

bool DemSolver::obstacle_pair(const SolidState& a, std::size_t obstacle,
                              ContactKinematics& k) const {
  const ShapeInfo& sa = shapes_[static_cast<std::size_t>(a.shape)];
  const double reach = sa.radius + cfg_.gap();
  const core::Box2 around{{a.x.x - reach, a.x.z - reach}, {a.x.x + reach, a.x.z + reach}};
  if (!obstacle_boxes_[obstacle].overlaps(around)) return false;
  auto& wa = scratch_a_;
  to_world(sa.body, pose_of(a), wa);
  const ClosestPoints cp = closest_points(wa, obstacles_[obstacle]);
  const double delta = cfg_.gap() - cp.distance;
  if (delta <= 0.0) return false;
  if (cp.distance > 1e-12 * sa.radius) {
    k.normal = (cp.on_b - cp.on_a) / cp.distance;
  } else {
    const Vec2 r = cp.on_b - a.x;
    if (core::norm(r) == 0.0) return false;
    k.normal = r / core::norm(r);
  }
  Vec2 on_a, on_b;
  face_weighted(cp, cfg_.gap(), on_a, on_b);
  k.point = 0.5 * (on_a + on_b);
  k.delta = delta;
  k.arm_a = on_a - a.x;
  return true;
}

// ---------------------------------------------------------------------------------------------
// eqs. 16-17: total contact force and moment on every owned solid

void DemSolver::collision_forces(double dt_t, Stage& out, std::vector<Springs>* new_springs,
                                 std::vector<Contact>* contacts) const {
  core::ScopedTimer timer("dem: collision forces");
  const std::size_t n_owned = owned_.size();
  out.force.assign(n_owned, Vec2{});
  out.torque.assign(n_owned, 0.0);
  if (new_springs) new_springs->assign(n_owned, Springs{});
  const bool accumulated = cfg_.tangential == TangentialModel::Accumulated;
  const BodyMotion fixed{};
  pair_slot_.resize(nbr_.size());
  pair_hits_.clear();
  const ContactLaw& law = *law_;
  for (std::size_t i = 0; i < n_owned; ++i) {
    const SolidState& s = owned_[i];
    Vec2 F{};
    double M = 0.0;
    auto add = [&](const ContactKinematics& kin, const Vec2& arm, const Vec2& f, double rolling,
                   std::int64_t key, double spring, std::int64_t other_id, bool report) {
      F += f;
      // torque arm x F, the arm to the solid's own contact point (eq. 9: F_eta R_i for circles)
      M += core::cross(arm, f);
      if (rolling != 0.0) M += rolling;  // rolling resistance (none by default: same bits)
      if (new_springs && accumulated) (*new_springs)[i].emplace_back(key, spring);
      if (contacts && report)
        contacts->push_back({s.id, other_id, kin.point, kin.normal, kin.delta});
    };
    ContactKinematics kin;
    // a tank wall or an obstacle (fixed, infinite mass) in contact with s
    auto against_fixed = [&](std::int64_t key) {
      auto coef = law.coefficients(s.mass, kFixedMass);
      // eq. 15's mu of the pair: the solid's own against the wall's or obstacle's dem/mu
      if (own_friction_) coef.mu = pair_friction(friction_of(s.id), cfg_.mu);
      const auto cf = law.force(coef, kin, motion_of(s), fixed,
                                accumulated ? spring_of(springs_[i], key) : 0.0, dt_t);
      add(kin, kin.arm_a, cf.force, cf.torque, key, cf.spring, -1, true);
    };
    for (int side = 0; side < 4; ++side)
      if (wall_pair(s, side, kin)) against_fixed(wall_key(side));
    for (int n = obs_start_[i]; n < obs_start_[i + 1]; ++n) {
      const auto o = static_cast<std::size_t>(obs_[static_cast<std::size_t>(n)]);
      if (obstacle_pair(s, o, kin)) against_fixed(obstacle_key(o));
    }
    for (int n = nbr_start_[i]; n < nbr_start_[i + 1]; ++n) {
      const auto e = static_cast<std::size_t>(n);
      const int j = nbr_[e];
      const SolidState& p = j < static_cast<int>(n_owned)
                                ? owned_[static_cast<std::size_t>(j)]
                                : ghosts_[static_cast<std::size_t>(j) - n_owned];
      // the pair is always evaluated with the lower id as body a: both owners get the same bits
      const bool i_is_a = s.id < p.id;
      const PairHit* hit = nullptr;
      if (mirror_[e] >= 0) {
        // evaluated at j's entry for i (j < i): the same bits as evaluating it again here
        const int slot = pair_slot_[static_cast<std::size_t>(mirror_[e])];
        if (slot >= 0) hit = &pair_hits_[static_cast<std::size_t>(slot)];
      } else {
        pair_slot_[e] = -1;
        const SolidState& a = i_is_a ? s : p;
        const SolidState& b = i_is_a ? p : s;
        if (solid_pair(a, b, kin)) {
          auto coef = law.coefficients(a.mass, b.mass);
          if (own_friction_) coef.mu = pair_friction(friction_of(a.id), friction_of(b.id));
          const auto cf = law.force(coef, kin, motion_of(a), motion_of(b),
                                    accumulated ? spring_of(springs_[i], p.id) : 0.0, dt_t);
          pair_slot_[e] = static_cast<int>(pair_hits_.size());
          pair_hits_.push_back({kin, cf});
          hit = &pair_hits_.back();
        }
      }
      if (!hit) continue;
      const ContactForce& cf = hit->cf;
      add(hit->kin, i_is_a ? hit->kin.arm_a : hit->kin.arm_b, i_is_a ? cf.force : -cf.force,
          i_is_a ? cf.torque : -cf.torque, p.id, cf.spring, p.id, i_is_a);
    }
    out.force[i] = F;
    out.torque[i] = M;
  }
}

std::vector<SolidLoads> DemSolver::predicted_collision_loads(double dt) const {
  Stage st;
  collision_forces(dt, st, nullptr, nullptr);
  std::vector<SolidLoads> loads(owned_.size());
  for (std::size_t i = 0; i < owned_.size(); ++i)
    loads[i] = {owned_[i].id, st.force[i], st.torque[i]};
  return loads;
}

std::vector<Contact> DemSolver::active_contacts() const {
  Stage st;
  std::vector<Contact> contacts;
  collision_forces(dt_dem_, st, nullptr, &contacts);
  return contacts;
}

// ---------------------------------------------------------------------------------------------
// eqs. 21-25: subcycles with the fluid loads held fixed

void DemSolver::advance(double dt, const std::vector<SolidLoads>& fluid_loads) {
  core::ScopedTimer timer("dem: advance");
  if (!(dt > 0.0)) {
    std::ostringstream m;
    m << "DemSolver::advance: dt = " << dt << "; allowed: > 0";
    throw core::SolverError(m.str());
  }
  // K = INT(dt / dt_DEM), dt_DEM = dt / K; eq. 25: dt_DEM = dt if dt_DEM > dt
  const double cycles = std::floor(dt / dt_dem_);
  if (!(cycles <= static_cast<double>(std::numeric_limits<int>::max()))) {
    // a converted count beyond int would be undefined (it became one subcycle of the whole dt)
    std::ostringstream m;
    m << "DemSolver::advance: dt = " << dt << " s needs " << cycles
      << " subcycles of dt_DEM = " << dt_dem_ << " s, more than " << std::numeric_limits<int>::max()
      << "; lower time/dt_max (dt_DEM is eq. 18's step or, with a large dem/alpha, the damped "
         "stability limit: doc/dem.md; it follows the solids' masses, here "
      << mass_range_.first << " to " << mass_range_.second
      << " kg per m: check the smallest solid's size and density)";
    throw core::SolverError(m.str());
  }
  const int K = std::max(1, static_cast<int>(cycles));
  const double h = dt / K;
  last_subcycles_ = K;

  // step (1): U_0 = U^n + (M^-1 F_fluid + g) dt, X_0 = X^n
  kick(fluid_loads, cfg_.gravity, dt, owned_, v_start_, omega_start_);
  forward();

  const bool paper = cfg_.position_update == PositionUpdate::StepStart;
  Stage a, b;
  std::vector<Springs> new_springs;
  std::vector<SolidState> prev;
  for (int k = 1; k <= K; ++k) {
    collision_forces(h, a, nullptr, nullptr);
    prev = owned_;
    for (std::size_t i = 0; i < owned_.size(); ++i) {
      SolidState& s = owned_[i];
      const SolidState& p = prev[i];
      // eq. 21: U_a = U_{k-1} + dt_DEM M^-1 F_a(X_{k-1}, U_{k-1})
      s.v = p.v + (h / s.mass) * a.force[i];
      s.omega = p.omega + (h / s.inertia) * a.torque[i];
      // eq. 22: X_a = X_{k-1} + (U^n + U_a) / 2 dt_DEM
      step_position(s, p, paper ? v_start_[i] : p.v, paper ? omega_start_[i] : p.omega, h);
    }
    forward();
    collision_forces(h, b, &new_springs, nullptr);
    for (std::size_t i = 0; i < owned_.size(); ++i) {
      SolidState& s = owned_[i];
      const SolidState& p = prev[i];
      // eq. 23: U_k = U_{k-1} + dt_DEM M^-1 (F_a + F_b) / 2
      s.v = p.v + (0.5 * h / s.mass) * (a.force[i] + b.force[i]);
      s.omega = p.omega + (0.5 * h / s.inertia) * (a.torque[i] + b.torque[i]);
      // eq. 24: X_k = X_{k-1} + (U^n + U_k) / 2 dt_DEM
      step_position(s, p, paper ? v_start_[i] : p.v, paper ? omega_start_[i] : p.omega, h);
    }
    if (cfg_.tangential == TangentialModel::Accumulated) springs_.swap(new_springs);
    forward();
    maybe_rebuild();
  }
}

}  // namespace picdem::dem

#include "picdem/dem/parameters.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "picdem/core/error.hpp"
#include "picdem/dem/contact_law_registry.hpp"
#include "picdem/dem/dem_solver.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/geometry/shape_registry.hpp"

namespace picdem::dem {

using core::Vec2;

namespace {

void declare_motion(core::ParamSchema& v) {
  v.reals("velocity", {0.0, 0.0}, "initial velocity (u, w) of the centre of mass [m/s]").size(2, 2);
  v.real("omega", 0.0, "initial angular velocity, counter-clockwise [rad/s]");
  v.real("density", 0.0, "density [kg/m^3]").positive().is_required();
  v.real("friction", -1.0,
         "friction coefficient mu of these solids (eq. 15); a pair takes the smaller of its two, "
         "a tank wall or an obstacle has dem/mu (doc/dem.md); -1: dem/mu")
      .at_least(-1.0);
}

SolidSpec placed(const core::Params& s, const geometry::PlacedShape& p) {
  SolidSpec spec;
  spec.shape = p.shape;
  spec.density = p.density > 0.0 ? p.density : s.real("density");
  spec.state.x = p.pose.x;
  spec.state.theta = p.pose.theta;
  const auto v = s.reals("velocity");
  spec.state.v = {v[0], v[1]};
  spec.state.omega = s.real("omega");
  spec.friction = s.real("friction");
  if (spec.friction < 0.0 && spec.friction != -1.0) {
    std::ostringstream m;
    m << s.full_path("friction") << " = " << spec.friction << "; allowed: >= 0, or -1 (dem/mu)";
    throw core::InputError(m.str());
  }
  const auto mp = spec.shape->mass_properties();
  spec.state.mass = spec.density * mp.area;
  spec.state.inertia = spec.density * mp.polar_moment;
  return spec;
}

}  // namespace

void declare_parameters(core::ParamSchema& schema) {
  schema.section("dem", "Solid contacts (eqs. 7-19) and DEM subcycles (eqs. 21-25).");
  // the contact law and each law's own keys (contact_law_registry.hpp)
  std::vector<std::string> laws;
  for (const auto& law : contact_law_types()) laws.push_back(law.name);
  schema.string("dem/contact_law", laws.front(), laws,
                "contact law (doc/dem.md); each law's own keys follow");
  for (const auto& law : contact_law_types()) law.declare(schema);
  schema.real("dem/psi", 0.3, "Poisson ratio psi (eqs. 12-13)").non_negative().less_than(0.5);
  schema.real("dem/mu", 0.3, "maximum static friction coefficient mu (eq. 15)").non_negative();
  schema
      .real("dem/rolling_resistance", 0.0,
            "rolling resistance mu_r: torque mu_r R* |F_n| against the relative rolling "
            "(doc/dem.md; 0: none, as the paper)")
      .non_negative();
  schema.real("dem/theta", 0.01, "penetration coefficient theta of the normal stiffness (eq. 10)")
      .positive();
  schema.real("dem/gamma", 150.0, "time-step coefficient gamma (eq. 18)").positive();
  schema
      .real("dem/gap_cells", 2.0,
            "imaginary gap between real boundaries in cells (eq. 19); > 0: the contact forces "
            "start at the gap, and real boundaries that touch stop the run")
      .positive();
  schema.string("dem/tangential_model", "one_step", {"one_step", "accumulated"},
                "tangential spring: one-step displacement (paper eq. 8) or accumulated over the "
                "contact (Zhang et al. 2009)");
  schema.string("dem/position_update", "step_start", {"step_start", "subcycle_start"},
                "velocity paired with U_k in eqs. 22/24: U^n of the fluid step (paper) or U_{k-1}");
  schema.reals("dem/gravity", {0.0, -9.81}, "gravity (x, z) acting on the solids [m/s^2]")
      .size(2, 2);
  schema.real("dem/skin", 0.0, "neighbour-list skin [m] (0: a fifth of the largest solid radius)")
      .non_negative();

  // every registered shape type is a variant: its own keys, then the motion's
  auto& f = schema.family("solids", "The solids of the case; ids 0, 1, ... in file order.");
  for (const auto& type : geometry::shape_types()) {
    auto& v = f.variant(type.name, type.doc);
    type.declare(v);
    declare_motion(v);
  }
}

DemConfig config_from(const core::Params& p, double h) {
  DemConfig c;
  c.alpha = p.real("dem/alpha");
  c.psi = p.real("dem/psi");
  c.mu = p.real("dem/mu");
  c.mu_r = p.real("dem/rolling_resistance");
  c.theta = p.real("dem/theta");
  c.gamma = p.real("dem/gamma");
  c.gap_cells = p.real("dem/gap_cells");
  c.tangential = p.string("dem/tangential_model") == "accumulated" ? TangentialModel::Accumulated
                                                                   : TangentialModel::OneStep;
  c.position_update = p.string("dem/position_update") == "subcycle_start"
                          ? PositionUpdate::SubcycleStart
                          : PositionUpdate::StepStart;
  const auto g = p.reals("dem/gravity");
  c.gravity = {g[0], g[1]};
  c.g_stiffness = core::norm(c.gravity) > 0.0 ? core::norm(c.gravity) : 9.81;
  c.skin = p.real("dem/skin");
  if (!(h > 0.0)) {
    std::ostringstream m;
    m << "dem: cell size h = " << h << "; allowed: > 0";
    throw core::InputError(m.str());
  }
  c.h = h;
  if (c.theta >= c.gap_cells) {
    // eq. 10: the heaviest solid's weight alone presses a contact by theta h; from theta =
    // gap_cells on, a solid resting on another (or on the floor) has its real boundary on the
    // other's, which stops the run as an overlap at the first resting contact
    std::ostringstream m;
    m << "key 'dem/theta' = " << c.theta << " with 'dem/gap_cells' = " << c.gap_cells
      << ": eq. 10 sizes the contact stiffness so that the heaviest solid's weight alone presses a "
         "contact by theta cells, which reaches the whole imaginary gap: resting solids would "
         "touch with their real boundaries; allowed: dem/theta < dem/gap_cells (the paper: "
         "theta 0.01 with a gap of 2 cells; a stack of n solids presses its lowest contact "
         "about n times as far)";
    throw core::InputError(m.str());
  }
  c.contact_law = contact_law_type(p.string("dem/contact_law")).build(p, c);
  return c;
}

std::vector<SolidSpec> solids_from(const core::Params& params) {
  std::vector<SolidSpec> out;
  if (!params.has("solids")) return out;
  geometry::BuildContext ctx;
  if (params.has("grid/cell_size") && params.has("dem/gap_cells"))
    ctx.gap = params.real("dem/gap_cells") * params.real("grid/cell_size");
  for (const auto& name : params.sublist_names("solids")) {
    const core::Params s = params.sub("solids/" + name);
    for (const auto& p : geometry::shape_type(s.string("type")).build(s, ctx))
      out.push_back(placed(s, p));
  }
  for (std::size_t n = 0; n < out.size(); ++n) out[n].state.id = static_cast<std::int64_t>(n);
  return out;
}

std::unique_ptr<DemSolver> solver_from(const core::Params& params, core::Comm comm, double h,
                                       const core::Box2& tank, std::vector<core::Box2> regions,
                                       const std::vector<geometry::Obstacle>& obstacles,
                                       const std::vector<SolidSpec>& solids) {
  std::vector<std::vector<core::Vec2>> polygons;
  for (const auto& o : obstacles)
    for (const auto& polygon : o.polygons) polygons.push_back(polygon);
  auto dem =
      std::make_unique<DemSolver>(comm, config_from(params, h), std::move(regions), tank, polygons);
  dem->add_solids(solids);
  return dem;
}

}  // namespace picdem::dem

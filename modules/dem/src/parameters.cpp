#include "picdem/dem/parameters.hpp"

#include <cmath>
#include <memory>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/geometry/circle.hpp"
#include "picdem/geometry/polygon.hpp"

namespace picdem::dem {

using core::Vec2;

namespace {

void declare_motion(core::ParamSchema& v) {
  v.reals("velocity", {0.0, 0.0}, "initial velocity (u, w) of the centre of mass [m/s]").size(2, 2);
  v.real("omega", 0.0, "initial angular velocity, counter-clockwise [rad/s]");
  v.real("density", 0.0, "density [kg/m^3]").positive().is_required();
}

void declare_polygon_common(core::ParamSchema& v) {
  declare_motion(v);
  v.real("theta", 0.0, "initial rotation about the centroid, counter-clockwise [rad]");
}

SolidSpec placed(const core::Params& s, geometry::ShapePtr shape, Vec2 centre, double theta) {
  SolidSpec spec;
  spec.shape = std::move(shape);
  spec.density = s.real("density");
  spec.state.x = centre;
  spec.state.theta = theta;
  const auto v = s.reals("velocity");
  spec.state.v = {v[0], v[1]};
  spec.state.omega = s.real("omega");
  const auto mp = spec.shape->mass_properties();
  spec.state.mass = spec.density * mp.area;
  spec.state.inertia = spec.density * mp.polar_moment;
  return spec;
}

SolidSpec polygon_solid(const core::Params& s, const std::vector<Vec2>& vertices) {
  auto poly = std::make_shared<const geometry::Polygon>(vertices);
  // the input vertices are world coordinates at theta = 0: the centroid is the centre
  return placed(s, poly, poly->centroid_offset(), s.real("theta"));
}

}  // namespace

void declare_parameters(core::ParamSchema& schema) {
  schema.section("dem", "Solid contacts (eqs. 7-19) and DEM subcycles (eqs. 21-25).");
  schema.real("dem/alpha", 0.4, "damping tuning parameter alpha (eq. 11)").non_negative();
  schema.real("dem/psi", 0.3, "Poisson ratio psi (eqs. 12-13)").non_negative().less_than(0.5);
  schema.real("dem/mu", 0.3, "maximum static friction coefficient mu (eq. 15)").non_negative();
  schema.real("dem/theta", 0.01, "penetration coefficient theta of the normal stiffness (eq. 10)")
      .positive();
  schema.real("dem/gamma", 150.0, "time-step coefficient gamma (eq. 18)").positive();
  schema.real("dem/gap_cells", 2.0, "imaginary gap between real boundaries in cells (eq. 19)")
      .non_negative();
  schema.string("dem/tangential_model", "one_step", {"one_step", "accumulated"},
                "tangential spring: one-step displacement (paper eq. 8) or accumulated over the "
                "contact (Zhang et al. 2009)");
  schema.string("dem/position_update", "step_start", {"step_start", "subcycle_start"},
                "velocity paired with U_k in eqs. 22/24: U^n of the fluid step (paper) or U_{k-1}");
  schema.reals("dem/gravity", {0.0, -9.81}, "gravity (x, z) acting on the solids [m/s^2]")
      .size(2, 2);
  schema.real("dem/skin", 0.0, "neighbour-list skin [m] (0: a fifth of the largest solid radius)")
      .non_negative();

  auto& f = schema.family("solids", "The solids of the case; ids 0, 1, ... in file order.");
  auto& disk = f.variant("disk", "a circular cylinder");
  disk.real("radius", 0.0, "radius [m]").positive().is_required();
  disk.reals("center", {0.0, 0.0}, "initial centre (x, z) [m]").size(2, 2).is_required();
  declare_motion(disk);
  disk.real("theta", 0.0, "initial rotation [rad]");

  auto& poly = f.variant("polygon", "a simple polygon; its centroid is its centre");
  poly.reals("vertices", {},
             "x0, z0, x1, z1, ... counter-clockwise, world coordinates at theta = 0 "
             "[m]")
      .size(6, 1 << 20)
      .is_required();
  declare_polygon_common(poly);

  auto& pfile = f.variant("polygon_file", "a polygon read from a vertex file (one 'x z' per line)");
  pfile.string("file", "", {}, "vertex file, counter-clockwise, world coordinates at theta = 0")
      .is_required();
  pfile.reals("offset", {0.0, 0.0}, "shift (x, z) added to every vertex [m]").size(2, 2);
  declare_polygon_common(pfile);

  auto& stack = f.variant("cylinder_stack",
                          "layers of n, n-1, n, ... equal cylinders against a "
                          "wall, each layer in the hollows of the one below");
  stack.real("radius", 0.0, "cylinder radius [m]").positive().is_required();
  stack.integer("layers", 1, "number of layers").at_least(1);
  stack.integer("first_layer", 1, "cylinders in the bottom layer (n)").at_least(1);
  stack
      .real("gap", 0.0,
            "gap between neighbours and to the wall and floor [m] (0: dem/gap_cells "
            "x grid/cell_size)")
      .non_negative();
  stack.reals("corner", {0.0, 0.0}, "where the wall meets the floor (x, z) [m]").size(2, 2);
  stack.string("side", "left", {"left", "right"}, "the wall is on this side of the stack");
  declare_motion(stack);
}

DemConfig config_from(const core::Params& p, double h) {
  DemConfig c;
  c.alpha = p.real("dem/alpha");
  c.psi = p.real("dem/psi");
  c.mu = p.real("dem/mu");
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
  return c;
}

std::vector<SolidSpec> solids_from(const core::Params& params) {
  std::vector<SolidSpec> out;
  if (!params.has("solids")) return out;
  for (const auto& name : params.sublist_names("solids")) {
    const core::Params s = params.sub("solids/" + name);
    const std::string type = s.string("type");
    if (type == "disk") {
      const auto c = s.reals("center");
      out.push_back(placed(s, std::make_shared<const geometry::Circle>(s.real("radius")),
                           {c[0], c[1]}, s.real("theta")));
    } else if (type == "polygon") {
      const auto v = s.reals("vertices");
      if (v.size() % 2 != 0) {
        std::ostringstream m;
        m << "key '" << s.full_path("vertices") << "' has " << v.size()
          << " numbers; allowed: pairs x, z (an even count >= 6)";
        throw core::InputError(m.str());
      }
      std::vector<Vec2> verts;
      for (std::size_t n = 0; n + 1 < v.size(); n += 2) verts.push_back({v[n], v[n + 1]});
      out.push_back(polygon_solid(s, verts));
    } else if (type == "polygon_file") {
      const geometry::Polygon file_poly = geometry::Polygon::from_file(s.string("file"));
      const auto o = s.reals("offset");
      std::vector<Vec2> verts;
      for (const Vec2& v : file_poly.vertices())
        verts.push_back(v + file_poly.centroid_offset() + Vec2{o[0], o[1]});
      out.push_back(polygon_solid(s, verts));
    } else if (type == "cylinder_stack") {
      const double r = s.real("radius");
      double gap = s.real("gap");
      if (gap == 0.0 && params.has("grid/cell_size") && params.has("dem/gap_cells"))
        gap = params.real("dem/gap_cells") * params.real("grid/cell_size");
      const auto corner = s.reals("corner");
      const double dir = s.string("side") == "left" ? 1.0 : -1.0;
      const auto n0 = s.integer("first_layer");
      auto shape = std::make_shared<const geometry::Circle>(r);
      // neighbours in a layer are 2r + gap apart; a layer sits in the hollows of the one below,
      // touching both at the same gap: rise sqrt(3)/2 (2r + gap)
      const double pitch = 2.0 * r + gap, rise = 0.5 * std::sqrt(3.0) * pitch;
      for (long long layer = 0; layer < s.integer("layers"); ++layer) {
        const bool short_layer = layer % 2 == 1;
        const long long n = short_layer ? n0 - 1 : n0;
        for (long long c = 0; c < n; ++c) {
          const double along = gap + r + (short_layer ? 0.5 * pitch : 0.0) + c * pitch;
          out.push_back(
              placed(s, shape, {corner[0] + dir * along, corner[1] + gap + r + layer * rise}, 0.0));
        }
      }
    }
  }
  for (std::size_t n = 0; n < out.size(); ++n) out[n].state.id = static_cast<std::int64_t>(n);
  return out;
}

}  // namespace picdem::dem

#include "picdem/coupling/schema.hpp"

#include <sstream>

#include "picdem/dem/parameters.hpp"
#include "picdem/fluid/fluid.hpp"
#include "picdem/fluid/time_step.hpp"
#include "picdem/geometry/obstacles.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/checkpoint_files.hpp"
#include "picdem/io/output_parameters.hpp"
#include "picdem/particles/particles.hpp"
#include "picdem/particles/water.hpp"

namespace picdem::coupling {

namespace {

std::string vector_text(const std::vector<double>& v) {
  std::ostringstream o;
  o << '[';
  for (std::size_t k = 0; k < v.size(); ++k) o << (k ? ", " : "") << v[k];
  return o.str() + ']';
}

// The case's name (the time step's keys are fluid's: fluid/time_step.hpp).
void declare_case(core::ParamSchema& s) {
  s.section("case", "What the case is.");
  s.string("case/name", "unnamed", {}, "short name, used in output file headers");
}

// The fluid-solid coupling, and the check that needs several modules' keys.
void declare_coupling(core::ParamSchema& s) {
  s.section("coupling", "The fluid-solid coupling.");
  s.real("coupling/beta", 0.5,
         "gap damping (eq. 20): particle velocity factor at a contact point; 1 switches it off")
      .at_least(0.0)
      .at_most(1.0);
  s.boolean("coupling/hydrostatic_quadrature", true,
            "carry the cell pressure to each wetted piece along rho g in the solid loads "
            "(false: the cell-centre value, as the paper)");
  s.boolean("coupling/viscous_rigid_rows", false,
            "fluid/viscosity_scheme implicit: the solids' rigid velocities are unknowns of the "
            "viscous step (stable for light solids; 2 more solves per component and solid); "
            "false: the split, the fluid's wall value the solid's start-of-step velocity, unstable "
            "for solids much lighter than the fluid (doc/viscous.md)");
  s.boolean("coupling/mixture_cut_faces", false,
            "hand the particles the mixture velocity (E u + (h - E) U_body) / h of the faces "
            "bodies cut, not the fluid's velocity through the open length E (doc/coupling.md)");
  s.real("coupling/tiny_cell_fraction", 1e-3,
         "cut cells with a smaller fluid fraction are made solid (doc/geometry.md)")
      .at_least(0.0)
      .less_than(0.5);

  // The density correction spreads crowded particles, so reseeding's added ones are no longer
  // offset: the two together create water (the plain dam break +15.8%, doc/coupling.md) and a dam
  // break against a step and three bodies blew up at 0.24 s (h = 2.5 mm, 2026-12-07).
  s.check([](const core::Params& p, std::vector<std::string>& errors) {
    const double w = p.real("free_surface/density_correction");
    const long long m = p.integer("particles/min_per_cell");
    if (w > 0.0 && m > 0) {
      std::ostringstream o;
      o << "keys 'free_surface/density_correction' = " << w
        << " and 'particles/min_per_cell' = " << m
        << ": the density correction with reseeding creates water (the correction spreads the "
           "crowded particles, reseeding still adds to the thinned cells: +15.8% on the plain "
           "dam break; a dam break against a step and three bodies blew up at 0.24 s); allowed: "
           "particles/min_per_cell: 0 with the correction, as the cylinder cases set "
           "(doc/coupling.md, \"Density correction\")";
      errors.push_back(o.str());
    }
  });

  // Solids and water must feel the same gravity.
  s.check([](const core::Params& p, std::vector<std::string>& errors) {
    if (!p.sublist_names("water").empty() && !p.sublist_names("solids").empty() &&
        p.reals("dem/gravity") != p.reals("fluid/gravity"))
      errors.push_back("keys 'dem/gravity' = " + vector_text(p.reals("dem/gravity")) +
                       " and 'fluid/gravity' = " + vector_text(p.reals("fluid/gravity")) +
                       " differ; with water and solids in one case they must be the same: set "
                       "both (each defaults to [0, -9.81])");
  });
}

}  // namespace

core::ParamSchema case_schema() {
  // In the order of the reference (doc/parameters.md): sections, then the families.
  core::ParamSchema s;
  declare_case(s);
  fluid::declare_time_parameters(s);
  io::declare_output_parameters(s);
  fluid::declare_free_surface_parameters(s);
  declare_coupling(s);
  particles::declare_water_parameters(s);
  grid::declare_parameters(s);
  fluid::declare_parameters(s);
  particles::declare_parameters(s);
  geometry::declare_obstacle_parameters(s);
  dem::declare_parameters(s);
  io::declare_checkpoint_parameters(s);
  return s;
}

}  // namespace picdem::coupling

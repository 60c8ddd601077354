// The free_surface/ keys (fluid.hpp): how the fluid's free surface is taken from the particles
// (free_surface.hpp) and the density correction's settings, and their reading.
#include "picdem/fluid/fluid.hpp"

namespace picdem::fluid {

void declare_free_surface_parameters(core::ParamSchema& s) {
  s.section("free_surface", "The free surface from the particles (doc/coupling.md).");
  s.string("free_surface/method", "ghost_fluid", {"ghost_fluid", "cells"},
           "p = 0 on the particles' level set S = 1/2 between cell centres (ghost fluid), or at "
           "the centres of cells without particles");
  s.real("free_surface/theta_min", 0.01,
         "smallest distance fraction of a fluid-air face to the surface (ghost fluid)")
      .greater_than(0.0)
      .at_most(1.0);
  s.boolean("free_surface/theta_open_length", false,
            "on fluid-air faces a body or obstacle cuts (open length E < h), theta >= theta_min "
            "h / E: the surface's gradient drives at most E / h of a full face's velocity "
            "through a sliver (doc/coupling.md)");
  s.real("free_surface/density_correction", 0.0,
         "share of the particles' excess or missing density (S - 1) moved away each step, "
         "positions only (doc/coupling.md); 0: off")
      .at_least(0.0)
      .at_most(1.0);
  s.integer("free_surface/density_correction_interval", 1,
            "steps between density corrections (each costs a second Poisson solve)")
      .at_least(1);
}

FreeSurfaceConfig free_surface_config_from(const core::Params& params) {
  FreeSurfaceConfig c;
  c.ghost_fluid = params.string("free_surface/method") == "ghost_fluid";
  c.theta_min = params.real("free_surface/theta_min");
  c.theta_open_length = params.boolean("free_surface/theta_open_length");
  c.density_relaxation = params.real("free_surface/density_correction");
  c.density_interval = params.integer("free_surface/density_correction_interval");
  return c;
}

}  // namespace picdem::fluid

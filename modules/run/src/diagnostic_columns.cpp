#include "diagnostic_columns.hpp"

#include <stdexcept>

namespace picdem::run {

const std::vector<std::string>& diagnostic_names() {
  static const std::vector<std::string> names{"t",
                                              "dt",
                                              "step",
                                              "fluid_volume",
                                              "kinetic_energy",
                                              "ppe_iterations",
                                              "ppe_residual",
                                              "front_x",
                                              "particles",
                                              "max_speed",
                                              "solid_kinetic_energy"};
  return names;
}

std::vector<double> diagnostic_scalars(const coupling::Diagnostics& g) {
  return {g.t,
          g.dt,
          static_cast<double>(g.step),
          g.fluid_volume,
          g.kinetic_energy,
          static_cast<double>(g.ppe_iterations),
          g.ppe_residual,
          g.front_x,
          static_cast<double>(g.particles),
          g.max_speed,
          g.solid_kinetic_energy};
}

void set_diagnostic_scalars(coupling::Diagnostics& g, const std::vector<double>& v) {
  if (v.size() != diagnostic_names().size())
    throw std::invalid_argument("set_diagnostic_scalars: " + std::to_string(v.size()) +
                                " values, expected " + std::to_string(diagnostic_names().size()));
  g.t = v[0], g.dt = v[1], g.step = static_cast<long long>(v[2]);
  g.fluid_volume = v[3], g.kinetic_energy = v[4];
  g.ppe_iterations = static_cast<int>(v[5]);
  g.ppe_residual = v[6], g.front_x = v[7], g.particles = static_cast<long long>(v[8]);
  g.max_speed = v[9], g.solid_kinetic_energy = v[10];
}

}  // namespace picdem::run

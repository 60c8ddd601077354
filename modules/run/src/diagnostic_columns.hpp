#pragma once
// The step's scalar figures (coupling::Diagnostics) as the run writes them: the first columns of
// timeseries.csv and the checkpoint's 'diagnostics' attribute. Private to the run module.
#include <string>
#include <vector>

#include "picdem/coupling/simulation.hpp"

namespace picdem::run {

/// The names of the scalar figures from t to solid_kinetic_energy, in their order.
const std::vector<std::string>& diagnostic_names();
/// The scalar figures of `g` in the order of diagnostic_names().
std::vector<double> diagnostic_scalars(const coupling::Diagnostics& g);
/// Sets the scalar figures of `g` from `v`; throws std::invalid_argument when v does not hold
/// diagnostic_names().size() values.
void set_diagnostic_scalars(coupling::Diagnostics& g, const std::vector<double>& v);

}  // namespace picdem::run

// The exact Stokes drag of a cylinder of radius a translating at the centre of a fixed concentric
// cylinder of radius b (Happel & Brenner 1965; the biharmonic stream function A r^3 + B r ln r +
// C r + D / r times sin theta with no-slip on both circles, doc/viscous.md): F = 4 pi mu U / K per
// unit length, K = ln(b / a) - (b^2 - a^2) / (b^2 + a^2). The settling and rising disks of
// cases/settling_disk_ring and cases/rising_disk_ring are checked against its terminal speed.
#pragma once

#include <cmath>

namespace picdem::test_support {

/// Terminal speed U_t = |rho_s - rho_f| g a^2 K / (4 mu) [m/s] of a disk of radius a and density
/// rho_s at the centre of a fixed ring of radius b in a fluid of density rho_f and viscosity nu.
inline double ring_stokes_terminal_speed(double a, double b, double rho_s, double rho_f, double nu,
                                         double g = 9.81) {
  const double K = std::log(b / a) - (b * b - a * a) / (b * b + a * a);
  return std::abs(rho_s - rho_f) * g * a * a * K / (4.0 * rho_f * nu);
}

}  // namespace picdem::test_support

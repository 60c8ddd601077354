#pragma once
// Graded packings (doc/shapes.md, "graded_packing"): solid sizes drawn from a grading curve,
// shapes and densities per class, placed without overlap in a box, every rank drawing the same
// packing from the same seed (no communication: the generator is a pure function of its keys).
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "picdem/geometry/shape_registry.hpp"

namespace picdem::geometry {

/// A grading curve: the fraction passing each sieve, interpolated linearly in log d between
/// sieves (the usual semi-log grading plot). The size d of a solid is its equivalent-area
/// diameter (area = pi d^2 / 4), so a solid's mass is proportional to d^2 whatever its shape.
class GradingCurve {
 public:
  /// `sieves` strictly increasing and > 0 [m], `passing` the same length, non-decreasing, 0 at
  /// the first sieve and 1 at the last. `by_mass`: passing fractions of mass (as a sieve
  /// analysis gives them), else of the number of solids. Throws core::InputError naming
  /// `what` + "/sieves" or "/passing".
  GradingCurve(std::vector<double> sieves, std::vector<double> passing, bool by_mass,
               const std::string& what);
  /// The size of the solid at number quantile u in [0, 1): the inverse of the number
  /// distribution that gives the curve (for by_mass the number density is the mass density
  /// divided by d^2).
  double sample(double u) const;
  /// Fraction passing size d, on the curve's own basis.
  double passing_at(double d) const;
  const std::vector<double>& sieves() const { return sieves_; }
  const std::vector<double>& passing() const { return passing_; }
  bool by_mass() const { return by_mass_; }

 private:
  std::vector<double> sieves_, passing_;
  bool by_mass_;
  std::vector<double> number_cdf_;  ///< number fraction below each sieve
};

/// Uniform numbers in [0, 1) from the 53 high bits of std::mt19937_64 (whose output the C++
/// standard fixes), so a seed gives the same packing on every rank and every compiler.
class PackingRandom {
 public:
  explicit PackingRandom(std::uint64_t seed);
  double uniform();
  /// An integer in [lo, hi].
  long long integer(long long lo, long long hi);

 private:
  std::mt19937_64 engine_;
};

/// One solid to place: its shape (body frame), orientation and class density.
struct PackingItem {
  ShapePtr shape;
  double theta = 0.0;
  double density = 0.0;
  double size = 0.0;  ///< equivalent-area diameter d [m]
};

/// The box [x0, x1] x [z0, z1] and how solids enter it.
struct PackingRegion {
  double x0 = 0.0, z0 = 0.0, x1 = 0.0, z1 = 0.0;
  bool pour = false;       ///< false: random sequential addition anywhere in the box, largest first
  long long tries = 1000;  ///< box: random positions tried per solid before giving up
  long long drops = 8;     ///< pour: drop columns tried per solid, the lowest landing kept
};

/// Places the items (their bounding circles at least `gap` apart and from the box's sides)
/// and returns them in placement order. Throws core::InputError naming `what` when a solid finds
/// no place: the region cannot hold the request.
std::vector<PlacedShape> place_packing(std::vector<PackingItem> items, const PackingRegion& region,
                                       double gap, const std::string& what, PackingRandom& rng);

}  // namespace picdem::geometry

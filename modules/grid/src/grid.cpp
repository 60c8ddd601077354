#include "picdem/grid/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "picdem/core/error.hpp"
#include "picdem/grid/field.hpp"

namespace picdem::grid {

void GridSpec::cell_of(const Vec2& p, int& i, int& k) const {
  i = static_cast<int>(std::floor((p.x - origin.x) / h));
  k = static_cast<int>(std::floor((p.z - origin.z) / h));
}

void declare_parameters(core::ParamSchema& schema) {
  schema.section("grid",
                 "The tank and its staggered grid of square cells. The tank walls are the "
                 "grid's outer faces.");
  schema.real("grid/length", 1.0, "tank length along x [m]").positive();
  schema.real("grid/height", 1.0, "tank height along z [m]").positive();
  schema
      .real("grid/cell_size", 0.01,
            "cell size h [m]; length and height are rounded to whole "
            "cells")
      .positive();
  schema.reals("grid/origin", {0.0, 0.0}, "position (x, z) of the tank's lower-left corner [m]")
      .size(2, 2);
  schema.integer("grid/ranks_x", 0, "ranks along x (0: chosen to cut the fewest faces)")
      .non_negative();
  schema.integer("grid/ranks_z", 0, "ranks along z (0: chosen with ranks_x)").non_negative();
  schema.string("grid/decomposition", "weighted", {"weighted", "uniform"},
                "weighted: the column and row cut lines balance the work of the cells (fluid "
                "cells and particles; in a dry run the solids), and the process grid is the one "
                "with the lightest heaviest block; uniform: equal strips (doc/performance.md)");
  schema
      .integer("grid/rebalance_interval", 25,
               "weighted: the cut lines are recomputed every this many steps (from the step "
               "number, so that a restart rebalances as the uninterrupted run); 0: only at the "
               "start")
      .non_negative();
  schema
      .real("grid/rebalance_gain", 0.05,
            "weighted: new cut lines are taken when they lighten the heaviest block by at least "
            "this fraction of its work")
      .non_negative()
      .at_most(0.9);
  schema.check([](const core::Params& p, std::vector<std::string>& errors) {
    const double h = p.real("grid/cell_size");
    for (const char* key : {"grid/length", "grid/height"}) {
      const double n = p.real(key) / h;
      if (n < 4.0 || n > 1e7) {
        std::ostringstream s;
        s << "key '" << key << "' = " << p.real(key) << " is " << n
          << " cells of grid/cell_size = " << h << "; allowed: 4 to 1e7 cells";
        errors.push_back(s.str());
      }
    }
  });
}

GridSpec spec_from(const core::Params& params) {
  GridSpec s;
  s.h = params.real("grid/cell_size");
  s.nx = static_cast<int>(std::lround(params.real("grid/length") / s.h));
  s.nz = static_cast<int>(std::lround(params.real("grid/height") / s.h));
  const auto o = params.reals("grid/origin");
  s.origin = {o[0], o[1]};
  return s;
}

namespace {
std::vector<int> split(int n, int parts) {
  std::vector<int> starts(static_cast<std::size_t>(parts) + 1);
  for (int p = 0; p <= parts; ++p)
    starts[static_cast<std::size_t>(p)] = static_cast<int>(static_cast<long long>(n) * p / parts);
  return starts;
}
}  // namespace

Decomposition::Decomposition(const GridSpec& spec, core::Comm comm, int halo, int px, int pz)
    : spec_(spec), comm_(comm), rank_(comm.rank()), halo_(halo) {
  const int p = comm.size();
  if (px <= 0 && pz <= 0) {
    // Fewest cut faces: each cut along x costs nz faces, along z nx faces.
    long long best = std::numeric_limits<long long>::max();
    for (int a = 1; a <= p; ++a) {
      if (p % a) continue;
      const int b = p / a;
      if (spec.nx / a < halo + 1 || spec.nz / b < halo + 1) continue;
      const long long cost =
          static_cast<long long>(a - 1) * spec.nz + static_cast<long long>(b - 1) * spec.nx;
      if (cost < best) best = cost, px = a, pz = b;
    }
  } else if (px <= 0) {
    px = p / pz;
  } else if (pz <= 0) {
    pz = p / px;
  }
  if (px <= 0 || pz <= 0 || px * pz != p) {
    std::ostringstream s;
    s << "cannot split the " << spec.nx << " x " << spec.nz << " grid over " << p
      << " ranks (grid/ranks_x = " << px << ", grid/ranks_z = " << pz
      << "): ranks_x * ranks_z must equal the number of ranks and every block must be at least "
      << halo + 1 << " cells wide";
    throw core::InputError(s.str());
  }
  if (spec.nx / px < halo + 1 || spec.nz / pz < halo + 1) {
    std::ostringstream s;
    s << "the " << spec.nx << " x " << spec.nz << " grid is too small for " << px << " x " << pz
      << " ranks: blocks must be at least " << halo + 1 << " cells wide";
    throw core::InputError(s.str());
  }
  px_ = px;
  pz_ = pz;
  xs_ = split(spec.nx, px);
  zs_ = split(spec.nz, pz);
}

void Decomposition::set_cuts(std::vector<int> xs, std::vector<int> zs) {
  auto valid = [&](const std::vector<int>& c, int n) {
    if (c.size() < 2 || c.front() != 0 || c.back() != n) return false;
    for (std::size_t j = 1; j < c.size(); ++j)
      if (c[j] - c[j - 1] < halo_ + 1) return false;
    return true;
  };
  const int px = static_cast<int>(xs.size()) - 1, pz = static_cast<int>(zs.size()) - 1;
  if (!valid(xs, spec_.nx) || !valid(zs, spec_.nz) || px * pz != comm_.size())
    throw std::invalid_argument("Decomposition::set_cuts: cut lines do not tile the grid over " +
                                std::to_string(comm_.size()) + " ranks in strips of at least " +
                                std::to_string(halo_ + 1) + " cells");
  px_ = px, pz_ = pz;
  xs_ = std::move(xs), zs_ = std::move(zs);
}

IndexBox Decomposition::provided(Stagger s, int rank) const {
  IndexBox b = owned(s, rank);
  const IndexBox e = spec_.extent(s);
  if (b.i0 == e.i0) b.i0 -= halo_;
  if (b.i1 == e.i1) b.i1 += halo_;
  if (b.k0 == e.k0) b.k0 -= halo_;
  if (b.k1 == e.k1) b.k1 += halo_;
  return b;
}

IndexBox Decomposition::owned_cells(int rank) const {
  const int cx = rank % px_, cz = rank / px_;
  return {xs_[static_cast<std::size_t>(cx)], xs_[static_cast<std::size_t>(cx) + 1],
          zs_[static_cast<std::size_t>(cz)], zs_[static_cast<std::size_t>(cz) + 1]};
}

IndexBox Decomposition::owned(Stagger s, int rank) const {
  IndexBox b = owned_cells(rank);
  if (s == Stagger::FaceX && b.i1 == spec_.nx) b.i1 += 1;
  if (s == Stagger::FaceZ && b.k1 == spec_.nz) b.k1 += 1;
  return b;
}

int Decomposition::owner_of_cell(int i, int k) const {
  i = std::min(std::max(i, 0), spec_.nx - 1);
  k = std::min(std::max(k, 0), spec_.nz - 1);
  // The strip holding i: the last start <= i.
  const int cx =
      static_cast<int>(std::upper_bound(xs_.begin() + 1, xs_.end() - 1, i) - xs_.begin()) - 1;
  const int cz =
      static_cast<int>(std::upper_bound(zs_.begin() + 1, zs_.end() - 1, k) - zs_.begin()) - 1;
  return cz * px_ + cx;
}

int Decomposition::owner_of_point(const Vec2& p) const {
  int i, k;
  spec_.cell_of(p, i, k);
  return owner_of_cell(i, k);
}

Halo::Halo(const Decomposition& d) : comm_(d.comm().raw()) {
  for (Stagger s : {Stagger::Cell, Stagger::FaceX, Stagger::FaceZ}) {
    auto& ls = links_[static_cast<int>(s)];
    for (int r = 0; r < d.size(); ++r) {
      if (r == d.rank()) continue;
      const IndexBox a = d.owned(s).intersect(d.storage(s, r));
      const IndexBox b = d.owned(s, r).intersect(d.storage(s));
      if (a.empty() && b.empty()) continue;
      ls.push_back({r, a.empty() ? IndexBox{} : a, b.empty() ? IndexBox{} : b});
    }
  }
}

std::vector<core::Box2> owned_regions(const Decomposition& d) {
  std::vector<core::Box2> out;
  const auto& s = d.spec();
  for (int r = 0; r < d.size(); ++r) {
    const auto b = d.owned_cells(r);
    out.push_back({{s.origin.x + b.i0 * s.h, s.origin.z + b.k0 * s.h},
                   {s.origin.x + b.i1 * s.h, s.origin.z + b.k1 * s.h}});
  }
  return out;
}

}  // namespace picdem::grid

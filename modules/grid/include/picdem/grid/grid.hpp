#pragma once
// The staggered (MAC) grid and its block decomposition over ranks.
//
// Cells (i, k), 0 <= i < nx, 0 <= k < nz, are squares of side h; cell (i, k) spans
// [x0 + i h, x0 + (i+1) h] x [z0 + k h, z0 + (k+1) h]. Pressure lives at cell centres, u on the
// vertical faces (FaceX, i in [0, nx]), w on the horizontal faces (FaceZ, k in [0, nz]).
// The grid covers the tank exactly: its outer faces are the tank walls.
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/params.hpp"
#include "picdem/core/vec2.hpp"

namespace picdem::grid {

using core::IndexBox;
using core::Vec2;

enum class Stagger { Cell, FaceX, FaceZ };

/// What fills a cell in the current step.
enum class CellState : signed char { Air = 0, Fluid = 1, Solid = 2 };

struct GridSpec {
  int nx = 0, nz = 0;
  double h = 0.0;
  Vec2 origin;

  double length() const { return nx * h; }
  double height() const { return nz * h; }
  /// Position of the sample point (i, k) of a staggered quantity.
  Vec2 position(Stagger s, int i, int k) const {
    const double ox = s == Stagger::FaceX ? 0.0 : 0.5, oz = s == Stagger::FaceZ ? 0.0 : 0.5;
    return {origin.x + (i + ox) * h, origin.z + (k + oz) * h};
  }
  /// Global index range of a staggered quantity over the whole grid.
  IndexBox extent(Stagger s) const {
    return {0, nx + (s == Stagger::FaceX ? 1 : 0), 0, nz + (s == Stagger::FaceZ ? 1 : 0)};
  }
  /// The cell holding p (cells are closed on their low sides); may lie outside the grid.
  void cell_of(const Vec2& p, int& i, int& k) const;
  long long cell_gid(int i, int k) const { return static_cast<long long>(k) * nx + i; }
};

/// Declares grid/length, grid/height, grid/cell_size, grid/origin, grid/ranks_x, grid/ranks_z,
/// grid/decomposition, grid/rebalance_interval, grid/rebalance_gain.
void declare_parameters(core::ParamSchema& schema);
/// Builds the spec from validated parameters (nx = length / cell_size rounded to a whole number).
GridSpec spec_from(const core::Params& params);

/// Block partition of the cells over a px x pz process grid; rank r holds block
/// (r % px, r / px). The blocks are a tensor product of px column strips and pz row strips,
/// whose cut lines need not be equally spaced. Every rank knows every block.
class Decomposition {
 public:
  /// Equal strips. px = pz = 0 chooses the process grid that cuts fewest faces. `halo` is the
  /// ghost width. Throws InputError when a block would be thinner than the halo.
  Decomposition(const GridSpec& spec, core::Comm comm, int halo, int px = 0, int pz = 0);

  /// Replaces the cut lines: xs = {0, ..., nx} (px + 1 strictly increasing starts), zs likewise,
  /// with px * pz = the rank count and every strip at least halo + 1 cells wide (else
  /// std::invalid_argument). The object keeps its identity: references to it see the new blocks.
  void set_cuts(std::vector<int> xs, std::vector<int> zs);
  const std::vector<int>& x_cuts() const { return xs_; }
  const std::vector<int>& z_cuts() const { return zs_; }
  /// The samples of a staggered quantity this rank provides when the blocks change: its owned
  /// samples, with the ghosts beyond the grid's outer sides it borders (so that the provided
  /// boxes of all ranks tile the extent grown by the halo).
  IndexBox provided(Stagger s, int rank) const;

  const GridSpec& spec() const { return spec_; }
  const core::Comm& comm() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return px_ * pz_; }
  int px() const { return px_; }
  int pz() const { return pz_; }
  int halo() const { return halo_; }

  IndexBox owned_cells(int rank) const;
  IndexBox owned_cells() const { return owned_cells(rank_); }
  /// Owned samples of a staggered quantity: those of the owned cells' low faces, plus the
  /// grid's last face for the last block along that direction.
  IndexBox owned(Stagger s, int rank) const;
  IndexBox owned(Stagger s) const { return owned(s, rank_); }
  /// Owned box grown by the halo on every side (may reach outside the grid).
  IndexBox storage(Stagger s, int rank) const { return owned(s, rank).grown(halo_); }
  IndexBox storage(Stagger s) const { return storage(s, rank_); }
  /// Rank owning cell (i, k); indices outside the grid are clamped to it.
  int owner_of_cell(int i, int k) const;
  int owner_of_point(const Vec2& p) const;

 private:
  GridSpec spec_;
  core::Comm comm_;
  int rank_ = 0, px_ = 1, pz_ = 1, halo_ = 0;
  std::vector<int> xs_, zs_;  // block starts, size px+1 / pz+1
};

/// The region of space each rank owns (its cells), by rank.
std::vector<core::Box2> owned_regions(const Decomposition& d);

}  // namespace picdem::grid

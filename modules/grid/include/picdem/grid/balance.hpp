#pragma once
// Cut lines that follow the work: the px column strips and pz row strips of a Decomposition
// chosen so that the heaviest block carries as little work as the tensor-product layout allows.
// The work of a cell is an integer (exact sums, the same on every rank count and in every
// reduction order), so the same state gives the same cut lines on 1 or N ranks.
#include <optional>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::grid {

struct Cuts {
  std::vector<int> xs, zs;  ///< strip starts, as Decomposition::set_cuts takes them
  long long heaviest = 0;   ///< the largest work of one block under these cuts
  long long total = 0;      ///< the work of the whole grid (balanced_cuts)
  long long before = 0;     ///< the heaviest block under the cuts they replace (worthwhile_cuts)
};

/// grid/decomposition and its rebalancing keys, read once from a validated case.
struct BalanceRule {
  bool weighted = false;         ///< grid/decomposition weighted
  int ranks_x = 0, ranks_z = 0;  ///< grid/ranks_x, grid/ranks_z (0: free)
  double gain = 0.0;             ///< grid/rebalance_gain
  long long interval = 0;        ///< grid/rebalance_interval (0: never after the first cuts)
  /// Whether the cut lines are computed again before step `step` (a step count > 0).
  bool due(long long step) const { return interval > 0 && step > 0 && step % interval == 0; }
};
BalanceRule balance_rule_from(const core::Params& params);

/// Splits the weights w[0..n) into `parts` consecutive strips of at least `min_width` entries,
/// each ending where the running sum comes nearest to its share of the total; returns the
/// parts + 1 strip starts. Needs parts * min_width <= n.
std::vector<int> split_weighted(const std::vector<long long>& w, int parts, int min_width);

/// Collective. `work`: the work of each of this rank's owned cells, row-major (i fastest).
/// For each process grid px x pz allowed by (ranks_x, ranks_z) (0: free, as for the
/// Decomposition) and by the minimum strip width halo + 1, the column cuts balance the column
/// sums and the row cuts the row sums. Of the process grids whose heaviest block is within 10% of
/// the lightest such block, the one with the most column strips wins. Throws InputError when no
/// process grid fits.
Cuts balanced_cuts(const Decomposition& d, const std::vector<long long>& work, int ranks_x,
                   int ranks_z);

/// Collective: the heaviest block's work under the decomposition's present cuts.
long long heaviest_block(const Decomposition& d, const std::vector<long long>& work);

/// The cut lines of a layout given by every rank's owned cell box (rank order), or empty cuts
/// when the boxes are not the tensor-product layout of `spec` over boxes.size() ranks.
Cuts cuts_of_boxes(const GridSpec& spec, const std::vector<IndexBox>& owned_cells);

/// Collective. weighted's new cut lines for the cells' `work` (balanced_cuts with the rule's
/// process grid): taken only when they differ from the decomposition's present cuts and make its
/// heaviest block lighter by the fraction rule.gain or more (Cuts::before: that block); nullopt
/// otherwise.
std::optional<Cuts> worthwhile_cuts(const Decomposition& d, const std::vector<long long>& work,
                                    const BalanceRule& rule);

/// "cut lines x {...}, z {...}, heaviest block <before> -> <heaviest> of <total>", for the log.
std::string describe(const Cuts& cuts);

/// The cut lines of a checkpoint's owned cell boxes (cuts_of_boxes, rank order) when they are a
/// layout of `ranks` ranks with the rule's ranks_x and ranks_z; empty cuts otherwise.
Cuts fitting_cuts_of_boxes(const GridSpec& spec, const std::vector<IndexBox>& owned_cells,
                           int ranks, const BalanceRule& rule);

}  // namespace picdem::grid

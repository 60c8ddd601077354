// The pressure system in Tpetra, its structure kept between solves (tpetra_system.hpp).
#include "tpetra_system.hpp"

#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <numeric>
#include <string>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::fluid::detail {

using Teuchos::RCP;
using Teuchos::rcp;

bool TpetraSystem::load(const RowContributions& rows, const std::vector<double>& x0,
                        const grid::Decomposition& d, bool rebalance) {
  const bool reuse = same_structure(rows, d.comm(), rebalance);
  if (!reuse) rebuild(rows, d, rebalance);
  {
    core::ScopedTimer timer("fluid: pressure values");
    fill_values(rows);
    fill_vectors(rows, x0);
  }
  return reuse;
}

bool TpetraSystem::same_structure(const RowContributions& rows, const core::Comm& comm,
                                  bool rebalance) const {
  const bool same = built_ && rebalance == rebalance_ && rows.cells == key_cells_ &&
                    rows.row == key_row_ && rows.col == key_col_;
  return !comm.any(!same);
}

void TpetraSystem::rebuild(const RowContributions& rows, const grid::Decomposition& d,
                           bool rebalance) {
  core::ScopedTimer timer("fluid: pressure structure");
  const core::Comm& comm = d.comm();
  const auto n = static_cast<long long>(rows.cells.size());
  const long long unknowns = comm.sum(n);
  offset_ = comm.exclusive_scan(n);
  tcomm_ = rcp(new Teuchos::MpiComm<int>(comm.raw()));
  // Unknowns are numbered contiguously over ranks (rank offset + local index): Amesos2's coarse
  // solve was measured to give wrong answers on maps of the non-contiguous cell ids.
  asm_map_ = rcp(new Map(static_cast<Tpetra::global_size_t>(unknowns), static_cast<std::size_t>(n),
                         0, tcomm_));
  build_source(rows, column_gids(rows, d));
  build_solve_side(rows, d, rebalance);
  key_cells_ = rows.cells, key_row_ = rows.row, key_col_ = rows.col;
  rebalance_ = rebalance;
  built_ = true;
}

/// The contiguous number of every contribution's column: owned cells by their row, the others
/// (halo neighbours, solid blocks) through their owner's answer on a map of the cell ids.
std::vector<TpetraSystem::GO> TpetraSystem::column_gids(const RowContributions& rows,
                                                        const grid::Decomposition& d) const {
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  grid::GridArray<int> local_of(d, grid::Stagger::Cell, -1);
  for (std::size_t r = 0; r < rows.cells.size(); ++r)
    local_of(static_cast<int>(rows.cells[r] % g.nx), static_cast<int>(rows.cells[r] / g.nx)) =
        static_cast<int>(r);
  auto owned_lid = [&](long long c) {
    const int i = static_cast<int>(c % g.nx), k = static_cast<int>(c / g.nx);
    return own.contains(i, k) ? local_of(i, k) : -1;
  };
  std::vector<GO> remote;
  for (long long c : rows.col)
    if (owned_lid(c) < 0) remote.push_back(c);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  std::vector<GO> cell_ids(rows.cells.begin(), rows.cells.end());
  const Map cell_map(invalid, Teuchos::ArrayView<const GO>(cell_ids.data(), cell_ids.size()), 0,
                     tcomm_);
  Teuchos::Array<int> pids(remote.size());
  Teuchos::Array<LO> lids(remote.size());
  cell_map.getRemoteIndexList(Teuchos::ArrayView<const GO>(remote.data(), remote.size()), pids(),
                              lids());
  const std::vector<double> offsets = d.comm().all_gather({static_cast<double>(offset_)});
  std::vector<GO> remote_gid(remote.size());
  for (std::size_t m = 0; m < remote.size(); ++m) {
    if (pids[m] < 0)
      throw core::SolverError("pressure matrix column of cell " + std::to_string(remote[m]) +
                              " is not a fluid cell on any rank");
    remote_gid[m] = static_cast<GO>(offsets[static_cast<std::size_t>(pids[m])]) + lids[m];
  }
  std::vector<GO> gid(rows.col.size());
  for (std::size_t c = 0; c < rows.col.size(); ++c) {
    const int lid = owned_lid(rows.col[c]);
    gid[c] =
        lid >= 0
            ? offset_ + lid
            : remote_gid[static_cast<std::size_t>(
                  std::lower_bound(remote.begin(), remote.end(), rows.col[c]) - remote.begin())];
  }
  return gid;
}

/// S on the assembly map from local CSR arrays: column map = own rows, then the other columns in
/// increasing number; the CSR slot of every contribution is kept for the refills.
void TpetraSystem::build_source(const RowContributions& rows, const std::vector<GO>& col_gid) {
  const auto n = static_cast<GO>(rows.cells.size());
  std::vector<GO> remote;
  for (GO c : col_gid)
    if (c < offset_ || c >= offset_ + n) remote.push_back(c);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<GO> col_gids(static_cast<std::size_t>(n));
  std::iota(col_gids.begin(), col_gids.end(), offset_);
  col_gids.insert(col_gids.end(), remote.begin(), remote.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  RCP<const Map> col_map = rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(col_gids.data(), col_gids.size()), 0, tcomm_));
  const std::size_t nc = col_gid.size();
  std::vector<LO> lid(nc);
  for (std::size_t c = 0; c < nc; ++c)
    lid[c] = col_gid[c] >= offset_ && col_gid[c] < offset_ + n
                 ? static_cast<LO>(col_gid[c] - offset_)
                 : static_cast<LO>(n + (std::lower_bound(remote.begin(), remote.end(), col_gid[c]) -
                                        remote.begin()));
  std::vector<std::size_t> order(nc);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rows.row[a] != rows.row[b] ? rows.row[a] < rows.row[b] : lid[a] < lid[b];
  });
  row_ptr_ = Teuchos::ArrayRCP<std::size_t>(static_cast<std::size_t>(n) + 1, 0);
  std::vector<LO> cols;
  pos_.assign(nc, 0);
  for (std::size_t m = 0; m < nc; ++m) {
    const std::size_t c = order[m];
    const bool fresh =
        m == 0 || rows.row[order[m - 1]] != rows.row[c] || lid[order[m - 1]] != lid[c];
    if (fresh) {
      cols.push_back(lid[c]);
      ++row_ptr_[static_cast<std::size_t>(rows.row[c]) + 1];
    }
    pos_[c] = cols.size() - 1;
  }
  for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) row_ptr_[r + 1] += row_ptr_[r];
  col_idx_ = Teuchos::ArrayRCP<LO>(cols.size());
  std::copy(cols.begin(), cols.end(), col_idx_.begin());
  values_.assign(cols.size(), 0.0);
  RCP<Graph> graph = rcp(new Graph(asm_map_, col_map, row_ptr_, col_idx_));
  graph->expertStaticFillComplete(asm_map_, asm_map_);
  S_ = rcp(new Matrix(RCP<const Graph>(graph)));
}

/// The solve map (an even split of the numbering, or the assembly map), the Export to it, A's
/// graph (S's rows sent there), the cell-centre coordinates and the vectors.
void TpetraSystem::build_solve_side(const RowContributions& rows, const grid::Decomposition& d,
                                    bool rebalance) {
  const core::Comm& comm = d.comm();
  const int P = comm.size(), q = comm.rank();
  const auto N = static_cast<long long>(asm_map_->getGlobalNumElements());
  RCP<MV> coords_asm = rcp(new MV(asm_map_, 2));
  {
    auto cx = coords_asm->getDataNonConst(0);
    auto cz = coords_asm->getDataNonConst(1);
    const grid::GridSpec& g = d.spec();
    for (std::size_t r = 0; r < rows.cells.size(); ++r) {
      const auto c = g.position(grid::Stagger::Cell, static_cast<int>(rows.cells[r] % g.nx),
                                static_cast<int>(rows.cells[r] / g.nx));
      cx[r] = c.x, cz[r] = c.z;
    }
  }
  // The grid's blocks hold unequal numbers of fluid cells (a dam break leaves whole blocks
  // dry): the rows are moved to an equal split of the same numbering, which keeps each rank's
  // rows a few contiguous strips of cells.
  if (!(rebalance && P > 1)) {
    solve_map_ = asm_map_, export_ = Teuchos::null, A_ = S_, coords_ = coords_asm;
    X_ = rcp(new MV(solve_map_, 1)), B_ = rcp(new MV(solve_map_, 1));
    X_asm_ = B_asm_ = Teuchos::null;
    return;
  }
  const long long lo = N * q / P, hi = N * (q + 1) / P;
  solve_map_ = rcp(
      new Map(static_cast<Tpetra::global_size_t>(N), static_cast<std::size_t>(hi - lo), 0, tcomm_));
  export_ = rcp(new Tpetra::Export<>(asm_map_, solve_map_));
  // A's rows have the lengths of S's rows they come from.
  Tpetra::Vector<double> len_asm(asm_map_), len(solve_map_);
  {
    auto v = len_asm.getDataNonConst();
    for (std::size_t r = 0; r < rows.cells.size(); ++r)
      v[r] = static_cast<double>(row_ptr_[r + 1] - row_ptr_[r]);
  }
  len.doExport(len_asm, *export_, Tpetra::INSERT);
  std::vector<std::size_t> counts;
  for (double v : len.getData()) counts.push_back(static_cast<std::size_t>(v));
  S_->fillComplete(asm_map_, asm_map_);  // values do not matter for the structure
  Matrix first(solve_map_, Teuchos::ArrayView<const std::size_t>(counts.data(), counts.size()));
  first.doExport(*S_, *export_, Tpetra::INSERT);
  first.fillComplete(solve_map_, solve_map_);
  A_ = rcp(new Matrix(first.getCrsGraph()));
  coords_ = rcp(new MV(solve_map_, 2));
  coords_->doExport(*coords_asm, *export_, Tpetra::INSERT);
  X_ = rcp(new MV(solve_map_, 1)), B_ = rcp(new MV(solve_map_, 1));
  X_asm_ = rcp(new MV(asm_map_, 1)), B_asm_ = rcp(new MV(asm_map_, 1));
}

/// Values of S from the contributions (summed per slot in contribution order), and A from S.
void TpetraSystem::fill_values(const RowContributions& rows) {
  std::fill(values_.begin(), values_.end(), 0.0);
  for (std::size_t c = 0; c < pos_.size(); ++c) values_[pos_[c]] += rows.val[c];
  if (S_->isFillComplete()) S_->resumeFill();
  for (std::size_t r = 0; r < rows.cells.size(); ++r) {
    const std::size_t b = row_ptr_[r], n = row_ptr_[r + 1] - b;
    S_->replaceLocalValues(static_cast<LO>(r), col_idx_.view(b, n),
                           Teuchos::ArrayView<const double>(values_.data() + b, n));
  }
  S_->fillComplete(asm_map_, asm_map_);
  if (export_.is_null()) return;
  // Rows assembled here but solved elsewhere: Export with ADD (each row of A comes from one rank).
  if (A_->isFillComplete()) A_->resumeFill();
  A_->setAllToScalar(0.0);
  A_->doExport(*S_, *export_, Tpetra::ADD);
  A_->fillComplete(solve_map_, solve_map_);
}

void TpetraSystem::fill_vectors(const RowContributions& rows, const std::vector<double>& x0) {
  const bool moved = !export_.is_null();
  {
    auto xv = (moved ? X_asm_ : X_)->getDataNonConst(0);
    auto bv = (moved ? B_asm_ : B_)->getDataNonConst(0);
    for (std::size_t r = 0; r < rows.cells.size(); ++r) xv[r] = x0[r], bv[r] = rows.rhs[r];
  }
  if (!moved) return;
  X_->doExport(*X_asm_, *export_, Tpetra::INSERT);
  B_->doExport(*B_asm_, *export_, Tpetra::INSERT);
}

std::vector<double> TpetraSystem::solution() const {
  if (!export_.is_null()) X_asm_->doImport(*X_, *export_, Tpetra::INSERT);
  const auto xv = (export_.is_null() ? X_ : X_asm_)->getData(0);
  return std::vector<double>(xv.begin(), xv.end());
}

}  // namespace picdem::fluid::detail

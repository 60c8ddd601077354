// The pressure system in Tpetra, its structure kept between solves (tpetra_system.hpp).
#include "tpetra_system.hpp"

#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::fluid::detail {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

using MV = Tpetra::MultiVector<>;
using Vec = Tpetra::Vector<>;

/// The pressure operator with the solids' blocks kept as a low-rank term (METHOD.md option (b)):
/// y = alpha (A + U W U^T - D) x + beta y, where A (MueLu's matrix) holds the fluid rows and
/// D = diag(U W U^T), which the operator takes out again. Symmetric, like the assembled matrix.
class LowRankOperator final : public Tpetra::Operator<> {
 public:
  LowRankOperator(RCP<const TpetraSystem::Matrix> A, RCP<const TpetraSystem::Matrix> U,
                  RCP<const Vec> w, RCP<const Vec> diag)
      : A_(std::move(A)), U_(std::move(U)), w_(std::move(w)), diag_(std::move(diag)) {}
  RCP<const TpetraSystem::Map> getDomainMap() const override { return A_->getDomainMap(); }
  RCP<const TpetraSystem::Map> getRangeMap() const override { return A_->getRangeMap(); }
  void apply(const MV& X, MV& Y, Teuchos::ETransp /*symmetric*/, double alpha,
             double beta) const override {
    const std::size_t nv = X.getNumVectors();
    if (z_.is_null() || z_->getNumVectors() != nv) {
      z_ = rcp(new MV(U_->getDomainMap(), nv)), wz_ = rcp(new MV(U_->getDomainMap(), nv));
      t_ = rcp(new MV(A_->getRangeMap(), nv));
    }
    // z = U^T x (the 3 per solid sums a_{s,c} . x over the cut cells), then W z = dt M^-1 z
    U_->apply(X, *z_, Teuchos::TRANS);
    wz_->elementWiseMultiply(1.0, *w_, *z_, 0.0);
    // t = A x + U (W U^T x) - D x
    A_->apply(X, *t_);
    U_->apply(*wz_, *t_, Teuchos::NO_TRANS, 1.0, 1.0);
    t_->elementWiseMultiply(-1.0, *diag_, X, 1.0);
    Y.update(alpha, *t_, beta);
  }

 private:
  RCP<const TpetraSystem::Matrix> A_, U_;
  RCP<const Vec> w_, diag_;
  mutable RCP<MV> z_, wz_, t_;
};

}  // namespace

bool TpetraSystem::load(const RowContributions& rows, const std::vector<double>& x0,
                        const grid::Decomposition& d, bool rebalance) {
  const bool reuse = rows.fixed ? fixed_slots(rows, d.comm(), rebalance)
                                : same_structure(rows, d.comm(), rebalance);
  if (!reuse) rebuild(rows, d, rebalance);
  {
    core::ScopedTimer timer("fluid: pressure values");
    fill_values(rows);
    fill_vectors(rows, x0);
  }
  if (rows.low_rank)
    build_low_rank(rows);
  else
    U_ = Teuchos::null, op_ = A_;
  return reuse;
}

/// U on the assembly rows from local CSR arrays, with the column map and the order in each row
/// that fillComplete gives a matrix filled by insertGlobalValues (the unknowns this rank owns in
/// solid_map ascending, then the others ascending; each row sorted by column, duplicates summed),
/// so the same matrix, without an insertion per entry and fillComplete's search for the columns.
RCP<TpetraSystem::Matrix> TpetraSystem::u_on_assembly_rows(const RowContributions& rows,
                                                           const RCP<const Map>& solid_map) const {
  const auto n_asm = static_cast<std::size_t>(asm_map_->getNodeNumElements());
  std::vector<GO> cols(rows.u_col.begin(), rows.u_col.end());
  std::sort(cols.begin(), cols.end());
  cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  std::stable_partition(cols.begin(), cols.end(),
                        [&](GO g) { return solid_map->isNodeGlobalElement(g); });
  std::vector<LO> lid_of(rows.weight.size(), -1);
  for (std::size_t l = 0; l < cols.size(); ++l)
    lid_of[static_cast<std::size_t>(cols[l])] = static_cast<LO>(l);
  // Entries bucketed by row in entry order, each row sorted by column (stable), duplicates summed.
  std::vector<std::size_t> ptr(n_asm + 1, 0);
  for (int r : rows.u_row) ++ptr[static_cast<std::size_t>(r) + 1];
  for (std::size_t r = 0; r < n_asm; ++r) ptr[r + 1] += ptr[r];
  std::vector<std::pair<LO, double>> e(rows.u_row.size());
  {
    std::vector<std::size_t> next(ptr.begin(), ptr.begin() + static_cast<std::ptrdiff_t>(n_asm));
    for (std::size_t m = 0; m < rows.u_row.size(); ++m)
      e[next[static_cast<std::size_t>(rows.u_row[m])]++] = {
          lid_of[static_cast<std::size_t>(rows.u_col[m])], rows.u_val[m]};
  }
  Teuchos::ArrayRCP<std::size_t> row_ptr(n_asm + 1, 0);
  std::size_t nnz = 0;
  for (std::size_t r = 0; r < n_asm; ++r) {
    const auto b = e.begin() + static_cast<std::ptrdiff_t>(ptr[r]);
    const auto end = e.begin() + static_cast<std::ptrdiff_t>(ptr[r + 1]);
    std::stable_sort(b, end, [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto it = b; it != end; ++it)
      if (nnz > row_ptr[r] && e[nnz - 1].first == it->first)
        e[nnz - 1].second += it->second;
      else
        e[nnz++] = *it;
    row_ptr[r + 1] = nnz;
  }
  Teuchos::ArrayRCP<LO> idx(nnz);
  Teuchos::ArrayRCP<double> val(nnz);
  for (std::size_t m = 0; m < nnz; ++m) idx[m] = e[m].first, val[m] = e[m].second;
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  RCP<const Map> col_map =
      rcp(new Map(invalid, Teuchos::ArrayView<const GO>(cols.data(), cols.size()), 0, tcomm_));
  RCP<Matrix> U = rcp(new Matrix(asm_map_, col_map, row_ptr, idx, val));
  U->expertStaticFillComplete(solid_map, asm_map_);
  return U;
}

/// U from its entries on the assembly rows (columns: the 3 per solid unknowns, split evenly over
/// the ranks), moved to the solve rows with the rows' Export; W and diag(U W U^T) likewise.
void TpetraSystem::build_low_rank(const RowContributions& rows) {
  core::ScopedTimer timer("fluid: pressure low-rank term");
  const auto n_asm = static_cast<std::size_t>(asm_map_->getNodeNumElements());
  RCP<const Map> solid_map =
      rcp(new Map(static_cast<Tpetra::global_size_t>(rows.weight.size()), 0, tcomm_));
  RCP<Matrix> U_asm = u_on_assembly_rows(rows, solid_map);
  RCP<Vec> w = rcp(new Vec(solid_map));
  {
    auto v = w->getDataNonConst();
    for (LO l = 0; l < static_cast<LO>(v.size()); ++l)
      v[l] = rows.weight[static_cast<std::size_t>(solid_map->getGlobalElement(l))];
  }
  RCP<Vec> diag_asm = rcp(new Vec(asm_map_)), diag = diag_asm;
  {
    auto v = diag_asm->getDataNonConst();
    for (std::size_t r = 0; r < n_asm; ++r) v[r] = rows.u_diag[r];
  }
  U_ = U_asm;
  if (!export_.is_null()) {
    U_ = Tpetra::exportAndFillCompleteCrsMatrix<Matrix>(RCP<const Matrix>(U_asm), *export_,
                                                        solid_map, solve_map_);
    diag = rcp(new Vec(solve_map_));
    diag->doExport(*diag_asm, *export_, Tpetra::INSERT);
  }
  op_ = rcp(new LowRankOperator(A_, U_, w, diag));
}

std::vector<double> TpetraSystem::apply(const std::vector<double>& x) const {
  const bool moved = !export_.is_null();
  MV x_asm(asm_map_, 1), y_asm(asm_map_, 1), xs(solve_map_, 1), ys(solve_map_, 1);
  {
    auto v = x_asm.getDataNonConst(0);
    for (std::size_t r = 0; r < x.size(); ++r) v[r] = x[r];
  }
  if (moved)
    xs.doExport(x_asm, *export_, Tpetra::INSERT);
  else
    xs.assign(x_asm);
  op_->apply(xs, ys);
  if (moved)
    y_asm.doImport(ys, *export_, Tpetra::INSERT);
  else
    y_asm.assign(ys);
  const auto v = y_asm.getData(0);
  return std::vector<double>(v.begin(), v.end());
}

long long TpetraSystem::matrix_entries() const {
  return static_cast<long long>(A_->getGlobalNumEntries());
}

long long TpetraSystem::low_rank_entries() const {
  return U_.is_null() ? 0 : static_cast<long long>(U_->getGlobalNumEntries());
}

bool TpetraSystem::same_structure(const RowContributions& rows, const core::Comm& comm,
                                  bool rebalance) const {
  const bool same = built_ && !fixed_ && rebalance == rebalance_ && rows.cells == key_cells_ &&
                    rows.row == key_row_ && rows.col == key_col_;
  return !comm.any(!same);
}

/// Fixed rows: the kept structure serves when the rows are the same cells and every
/// contribution's column is in its row; pos_ then holds the slots (found in the row's columns,
/// sorted, so a rebuild would give the same slots and the same sums).
bool TpetraSystem::fixed_slots(const RowContributions& rows, const core::Comm& comm,
                               bool rebalance) {
  bool ok = built_ && fixed_ && rebalance == rebalance_ && rows.cells == key_cells_;
  if (ok) {
    pos_.resize(rows.col.size());
    for (std::size_t c = 0; c < rows.col.size() && ok; ++c) {
      const int i = static_cast<int>(rows.col[c] % nx_), k = static_cast<int>(rows.col[c] / nx_);
      const int lid = col_of_.in_storage(i, k) ? col_of_(i, k) : -1;
      const auto r = static_cast<std::size_t>(rows.row[c]);
      const LO* b = col_idx_.getRawPtr() + row_ptr_[r];
      const LO* e = col_idx_.getRawPtr() + row_ptr_[r + 1];
      const LO* at = std::lower_bound(b, e, static_cast<LO>(lid));
      ok = lid >= 0 && at != e && *at == lid;
      if (ok) pos_[c] = static_cast<std::size_t>(at - col_idx_.getRawPtr());
    }
  }
  return !comm.any(!ok);
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
  std::vector<GO> col_gid;
  {
    core::ScopedTimer t("fluid: pressure structure 1 columns");
    col_gid = column_gids(rows, d);
  }
  {
    core::ScopedTimer t("fluid: pressure structure 2 assembly matrix");
    build_source(rows, col_gid, !(rebalance && d.comm().size() > 1));
  }
  {
    core::ScopedTimer t("fluid: pressure structure 3 solve matrix");
    build_solve_side(rows, d, rebalance);
  }
  key_cells_ = rows.cells, key_row_ = rows.row, key_col_ = rows.col;
  rebalance_ = rebalance, fixed_ = rows.fixed;
  nx_ = d.spec().nx;
  if (rows.fixed) {
    col_of_ = grid::GridArray<int>(d, grid::Stagger::Cell, -1);
    for (std::size_t c = 0; c < rows.col.size(); ++c) {
      const int i = static_cast<int>(rows.col[c] % nx_), k = static_cast<int>(rows.col[c] / nx_);
      if (col_of_.in_storage(i, k)) col_of_(i, k) = static_cast<int>(col_idx_[pos_[c]]);
    }
  }
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
  std::vector<GO> gid(rows.col.size());
  // Every column owned here on every rank (one rank): no map of the cell ids to ask.
  if (!d.comm().any(!remote.empty())) {
    for (std::size_t c = 0; c < rows.col.size(); ++c) gid[c] = offset_ + owned_lid(rows.col[c]);
    return gid;
  }
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
void TpetraSystem::build_source(const RowContributions& rows, const std::vector<GO>& col_gid,
                                bool make_matrix) {
  const auto n = static_cast<GO>(rows.cells.size());
  std::vector<GO> remote;
  for (GO c : col_gid)
    if (c < offset_ || c >= offset_ + n) remote.push_back(c);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<GO>& col_gids = s_col_gids_;
  col_gids.assign(static_cast<std::size_t>(n), 0);
  std::iota(col_gids.begin(), col_gids.end(), offset_);
  col_gids.insert(col_gids.end(), remote.begin(), remote.end());
  const std::size_t nc = col_gid.size();
  std::vector<LO> lid(nc);
  for (std::size_t c = 0; c < nc; ++c)
    lid[c] = col_gid[c] >= offset_ && col_gid[c] < offset_ + n
                 ? static_cast<LO>(col_gid[c] - offset_)
                 : static_cast<LO>(n + (std::lower_bound(remote.begin(), remote.end(), col_gid[c]) -
                                        remote.begin()));
  // Contributions bucketed by row (in contribution order), then each row's sorted by column.
  std::vector<std::size_t> first(static_cast<std::size_t>(n) + 1, 0), order(nc);
  for (std::size_t c = 0; c < nc; ++c) ++first[static_cast<std::size_t>(rows.row[c]) + 1];
  for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) first[r + 1] += first[r];
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t c = 0; c < nc; ++c) order[next[static_cast<std::size_t>(rows.row[c])]++] = c;
  }
  row_ptr_ = Teuchos::ArrayRCP<std::size_t>(static_cast<std::size_t>(n) + 1, 0);
  std::vector<LO> cols;
  cols.reserve(nc);
  pos_.assign(nc, 0);
  for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) {
    const auto b = order.begin() + static_cast<std::ptrdiff_t>(first[r]);
    const auto e = order.begin() + static_cast<std::ptrdiff_t>(first[r + 1]);
    // A fluid row holds at most 5 contributions: std::stable_sort's buffer (an allocation per
    // row) cost more than the sorting there, so short rows take a stable insertion sort (the
    // same order, so the same sums); long ones (an assembled solid block) std::stable_sort.
    if (e - b > 16)
      std::stable_sort(b, e, [&](std::size_t x, std::size_t y) { return lid[x] < lid[y]; });
    else
      for (auto it = b; it != e; ++it)
        for (auto at = it; at != b && lid[*(at - 1)] > lid[*at]; --at) std::iter_swap(at - 1, at);
    for (auto it = b; it != e; ++it) {
      if (it == b || lid[*(it - 1)] != lid[*it]) cols.push_back(lid[*it]);
      pos_[*it] = cols.size() - 1;
    }
    row_ptr_[r + 1] = cols.size();
  }
  col_idx_ = Teuchos::ArrayRCP<LO>(cols.size());
  std::copy(cols.begin(), cols.end(), col_idx_.begin());
  values_.assign(cols.size(), 0.0);
  S_ = Teuchos::null;
  if (!make_matrix) return;
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  RCP<const Map> col_map = rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(col_gids.data(), col_gids.size()), 0, tcomm_));
  RCP<Graph> graph = rcp(new Graph(asm_map_, col_map, row_ptr_, col_idx_));
  graph->expertStaticFillComplete(asm_map_, asm_map_);
  S_ = rcp(new Matrix(RCP<const Graph>(graph)));
}

/// The solve map (an even split of the numbering, or the assembly map), the Export to it, A's
/// graph (S's graph exported there), the cell-centre coordinates and the vectors.
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
  // A's rows have the lengths of the assembled rows they come from.
  Tpetra::Vector<double> len_asm(asm_map_), len(solve_map_);
  {
    auto v = len_asm.getDataNonConst();
    for (std::size_t r = 0; r < rows.cells.size(); ++r)
      v[r] = static_cast<double>(row_ptr_[r + 1] - row_ptr_[r]);
  }
  len.doExport(len_asm, *export_, Tpetra::INSERT);
  std::vector<std::size_t> counts;
  for (double v : len.getData()) counts.push_back(static_cast<std::size_t>(v));
  build_moved_rows(counts, comm, lo, hi);
  coords_ = rcp(new MV(solve_map_, 2));
  coords_->doExport(*coords_asm, *export_, Tpetra::INSERT);
  X_ = rcp(new MV(solve_map_, 1)), B_ = rcp(new MV(solve_map_, 1));
  X_asm_ = rcp(new MV(asm_map_, 1)), B_asm_ = rcp(new MV(asm_map_, 1));
}

/// The nonzeros are numbered contiguously in row order over the ranks; rows move whole, so the
/// nonzeros of the solve rows [lo, hi) are a contiguous range too and one Export of a vector over
/// the nonzeros moves their column numbers now and their values at every solve. A is built here
/// from local CSR arrays with a prepared column map (its own rows, then the others sorted), and
/// a_from_ says which received nonzero fills each of its slots.
void TpetraSystem::build_moved_rows(const std::vector<std::size_t>& counts, const core::Comm& comm,
                                    long long lo, long long hi) {
  const std::size_t nnz = row_ptr_[row_ptr_.size() - 1];
  std::size_t a_nnz = 0;
  for (std::size_t c : counts) a_nnz += c;
  const auto total = static_cast<Tpetra::global_size_t>(comm.sum(static_cast<long long>(nnz)));
  nnz_src_ = rcp(new Tpetra::Vector<>(rcp(new Map(total, nnz, 0, tcomm_))));
  nnz_dst_ = rcp(new Tpetra::Vector<>(rcp(new Map(total, a_nnz, 0, tcomm_))));
  nnz_export_ = rcp(new Tpetra::Export<>(nnz_src_->getMap(), nnz_dst_->getMap()));
  {
    auto v = nnz_src_->getDataNonConst();
    for (std::size_t j = 0; j < nnz; ++j)
      v[j] = static_cast<double>(s_col_gids_[static_cast<std::size_t>(col_idx_[j])]);
  }
  nnz_dst_->doExport(*nnz_src_, *nnz_export_, Tpetra::INSERT);
  const auto col = nnz_dst_->getData();
  std::vector<GO> remote;
  for (double c : col)
    if (static_cast<GO>(c) < lo || static_cast<GO>(c) >= hi) remote.push_back(static_cast<GO>(c));
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<GO> col_gids(static_cast<std::size_t>(hi - lo));
  std::iota(col_gids.begin(), col_gids.end(), lo);
  col_gids.insert(col_gids.end(), remote.begin(), remote.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  RCP<const Map> col_map = rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(col_gids.data(), col_gids.size()), 0, tcomm_));
  a_row_ptr_ = Teuchos::ArrayRCP<std::size_t>(counts.size() + 1, 0);
  a_col_idx_ = Teuchos::ArrayRCP<LO>(a_nnz);
  a_from_.assign(a_nnz, 0);
  std::vector<std::pair<LO, std::size_t>> row;
  for (std::size_t r = 0, k = 0; r < counts.size(); ++r) {
    row.clear();
    for (std::size_t m = 0; m < counts[r]; ++m, ++k) {
      const auto g = static_cast<GO>(col[k]);
      row.emplace_back(
          g >= lo && g < hi
              ? static_cast<LO>(g - lo)
              : static_cast<LO>(
                    hi - lo + (std::lower_bound(remote.begin(), remote.end(), g) - remote.begin())),
          k);
    }
    std::sort(row.begin(), row.end());
    const std::size_t b = a_row_ptr_[r];
    for (std::size_t m = 0; m < row.size(); ++m)
      a_col_idx_[b + m] = row[m].first, a_from_[b + m] = row[m].second;
    a_row_ptr_[r + 1] = b + row.size();
  }
  a_values_.assign(a_nnz, 0.0);
  RCP<Graph> graph = rcp(new Graph(solve_map_, col_map, a_row_ptr_, a_col_idx_));
  graph->expertStaticFillComplete(solve_map_, solve_map_);
  A_ = rcp(new Matrix(RCP<const Graph>(graph)));
}

/// The CSR values from the contributions (summed per slot in contribution order) into S = A, or
/// sent to the ranks that solve the rows (Export with ADD into zeros: each row comes from one
/// rank) and placed in A.
void TpetraSystem::fill_values(const RowContributions& rows) {
  std::fill(values_.begin(), values_.end(), 0.0);
  for (std::size_t c = 0; c < pos_.size(); ++c) values_[pos_[c]] += rows.val[c];
  const Teuchos::ArrayRCP<std::size_t>& ptr = export_.is_null() ? row_ptr_ : a_row_ptr_;
  const Teuchos::ArrayRCP<LO>& idx = export_.is_null() ? col_idx_ : a_col_idx_;
  const double* vals = values_.data();
  if (!export_.is_null()) {
    {
      auto v = nnz_src_->getDataNonConst();
      std::copy(values_.begin(), values_.end(), v.begin());
    }
    nnz_dst_->putScalar(0.0);
    nnz_dst_->doExport(*nnz_src_, *nnz_export_, Tpetra::ADD);
    const auto got = nnz_dst_->getData();
    for (std::size_t j = 0; j < a_values_.size(); ++j) a_values_[j] = got[a_from_[j]];
    vals = a_values_.data();
  }
  // A's graph is static and its rows are packed in the order of ptr/idx (the CSR arrays it was
  // built from), so the values go straight into its local values: no resumeFill, per-row
  // replaceLocalValues and fillComplete at every solve (the same values, so the same bits).
  // Checked once per structure, at its first fill.
  if (!A_->isFillComplete()) {
    A_->fillComplete(solve_map_, solve_map_);
    const auto g = A_->getCrsGraph()->getLocalGraphHost();
    bool same = g.row_map.extent(0) == static_cast<std::size_t>(ptr.size()) &&
                g.entries.extent(0) == static_cast<std::size_t>(idx.size());
    for (std::size_t r = 0; same && r < static_cast<std::size_t>(ptr.size()); ++r)
      same = static_cast<std::size_t>(g.row_map(r)) == ptr[r];
    for (std::size_t j = 0; same && j < static_cast<std::size_t>(idx.size()); ++j)
      same = g.entries(j) == idx[j];
    int all_same = same ? 1 : 0, local = all_same;  // every rank throws, or none
    Teuchos::reduceAll(*tcomm_, Teuchos::REDUCE_MIN, local, Teuchos::outArg(all_same));
    if (!all_same)
      throw core::SolverError("pressure matrix: Tpetra's local graph is not the kept CSR arrays");
  }
  const auto v = A_->getLocalValuesView();
  for (std::size_t j = 0; j < static_cast<std::size_t>(v.extent(0)); ++j) v(j) = vals[j];
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

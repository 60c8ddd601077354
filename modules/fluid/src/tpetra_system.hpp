#pragma once
// The pressure system in Tpetra, kept between solves (private to the fluid module; included only
// by tpetra_system.cpp and pressure_solver.cpp).
//
// Every rank assembles the rows of its owned fluid cells, numbered contiguously over the ranks
// (rank offset + local index), as local CSR arrays (the "assembly" map). Without rebalancing
// they are the CrsMatrix A, built with a prepared column map (own columns, then the others
// sorted) and expertStaticFillComplete. With solver/rebalance on several ranks the rows are
// solved on an even split of the same numbering (the "solve" map): the rows a rank assembled but
// does not own there are sent with Exports (ADD) to the rank that solves them (the rows it keeps
// are copied locally by the same Exports), and A is built there from local CSR arrays the same
// way. Maps, graphs, Exports, the CSR slot of every contribution and the vectors are kept while
// the structure (rows and the columns of every contribution, on every rank) is unchanged: a
// solve then only refills values.
//
// With the solids' term kept out of the matrix (RowContributions::low_rank), A holds the fluid
// rows plus the diagonal of the solids' blocks, and op() is A + U W U^T - diag(U W U^T): U (rows
// x 3 per solid, the rows a_{s,c}) is built at every load on the assembly rows and exported to
// the solve rows; the 3 per solid unknowns of U^T x are split evenly over the ranks.
//
// With fixed rows (RowContributions::fixed: every owned cell a row, the same columns at every
// solve), a load whose contributions all fall on the slots of the kept rows refills values only,
// whatever the fluid mask: the slots are looked up per contribution instead of compared.
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <vector>

#include "picdem/grid/field.hpp"
#include "pressure_rows.hpp"

namespace picdem::fluid::detail {

class TpetraSystem {
 public:
  using Map = Tpetra::Map<>;
  using Matrix = Tpetra::CrsMatrix<>;
  using Graph = Tpetra::CrsGraph<>;
  using MV = Tpetra::MultiVector<>;
  using LO = Map::local_ordinal_type;
  using GO = Map::global_ordinal_type;

  /// Takes this solve's rows and initial guess x0 (one per row). Rebuilds the structure when it
  /// differs from the last load on any rank, else refills the values only; returns true when the
  /// structure was reused. Collective.
  bool load(const RowContributions& rows, const std::vector<double>& x0,
            const grid::Decomposition& d, bool rebalance);

  /// The matrix MueLu is built on: the whole operator, or with the low-rank term the fluid
  /// rows and the diagonal of the solids' blocks.
  const Teuchos::RCP<Matrix>& matrix() const { return A_; }
  /// The operator CG solves with: matrix(), or matrix() + U W U^T - diag(U W U^T).
  const Teuchos::RCP<const Tpetra::Operator<>>& op() const { return op_; }
  /// op() applied to x (one value per row of the last load, this rank's rows). Collective.
  std::vector<double> apply(const std::vector<double>& x) const;
  /// Global entries of matrix() and of U (0 without the low-rank term).
  long long matrix_entries() const;
  long long low_rank_entries() const;
  const Teuchos::RCP<MV>& x() const { return X_; }
  const Teuchos::RCP<MV>& b() const { return B_; }
  const Teuchos::RCP<MV>& coordinates() const { return coords_; }
  /// The solution of x(), one value per row of the last load (this rank's rows).
  std::vector<double> solution() const;

 private:
  bool same_structure(const RowContributions& rows, const core::Comm& comm, bool rebalance) const;
  bool fixed_slots(const RowContributions& rows, const core::Comm& comm, bool rebalance);
  void rebuild(const RowContributions& rows, const grid::Decomposition& d, bool rebalance);
  std::vector<GO> column_gids(const RowContributions& rows, const grid::Decomposition& d) const;
  void build_source(const RowContributions& rows, const std::vector<GO>& col_gid, bool make_matrix);
  void build_solve_side(const RowContributions& rows, const grid::Decomposition& d, bool rebalance);
  void build_moved_rows(const std::vector<std::size_t>& counts, const core::Comm& comm,
                        long long lo, long long hi);
  void fill_values(const RowContributions& rows);
  void fill_vectors(const RowContributions& rows, const std::vector<double>& x0);
  void build_low_rank(const RowContributions& rows);
  Teuchos::RCP<Matrix> u_on_assembly_rows(const RowContributions& rows,
                                          const Teuchos::RCP<const Map>& solid_map) const;

  bool built_ = false, rebalance_ = false, fixed_ = false;
  long long nx_ = 0;
  grid::GridArray<int> col_of_;  // fixed: the CSR column of every stored cell, -1 if none
  std::vector<long long> key_cells_, key_col_;  // the structure of the last rebuild
  std::vector<int> key_row_;
  long long offset_ = 0;
  Teuchos::RCP<const Teuchos::Comm<int>> tcomm_;
  Teuchos::RCP<const Map> asm_map_, solve_map_;
  Teuchos::RCP<Matrix> S_, A_;
  Teuchos::RCP<Tpetra::Export<>> export_;
  Teuchos::ArrayRCP<std::size_t> row_ptr_;
  Teuchos::ArrayRCP<LO> col_idx_;
  std::vector<std::size_t> pos_;  // per contribution: its slot in the assembled CSR values
  std::vector<double> values_;    // assembled CSR values
  std::vector<GO> s_col_gids_;    // the assembled CSR's columns (local index -> number)
  // Rebalanced: the nonzeros moved by one Export, and A's CSR filled from what arrives.
  Teuchos::RCP<Tpetra::Vector<>> nnz_src_, nnz_dst_;
  Teuchos::RCP<Tpetra::Export<>> nnz_export_;
  Teuchos::ArrayRCP<std::size_t> a_row_ptr_;
  Teuchos::ArrayRCP<LO> a_col_idx_;
  std::vector<std::size_t> a_from_;
  std::vector<double> a_values_;
  Teuchos::RCP<MV> X_, B_, coords_, X_asm_, B_asm_;
  // The low-rank term: U on the solve rows, and the operator Belos applies.
  Teuchos::RCP<Matrix> U_;
  Teuchos::RCP<const Tpetra::Operator<>> op_;
};

}  // namespace picdem::fluid::detail

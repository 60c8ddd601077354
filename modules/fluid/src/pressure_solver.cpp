// Assembly of the augmented pressure equation (eqs. 5-6) into a Tpetra::CrsMatrix and its
// solution by Belos CG preconditioned with MueLu smoothed aggregation. The only file of the
// project that includes Tpetra, Belos or MueLu.
#include "picdem/fluid/pressure_solver.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_MasterList.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"
#include "solid_couplings.hpp"

namespace picdem::fluid {

namespace {

using Map = Tpetra::Map<>;
using Matrix = Tpetra::CrsMatrix<>;
using MV = Tpetra::MultiVector<>;
using OP = Tpetra::Operator<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Teuchos::RCP;
using Teuchos::rcp;

constexpr signed char kFluid = static_cast<signed char>(grid::CellState::Fluid);
constexpr signed char kSolid = static_cast<signed char>(grid::CellState::Solid);

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The linear-solver settings read once from the case: the declared lists of solver/Belos and
/// solver/MueLu, and the lists merged over MueLu's for systems with solids and for systems
/// solved on one level on several ranks (fluid::declare_parameters declares all four).
struct SolverSettings {
  double tolerance = 1e-8;
  int max_iterations = 500;
  bool rebalance = true;
  Teuchos::ParameterList belos, muelu, muelu_solids, muelu_one_level;
};

/// `over`'s keys merged over `base`. A "smoother: params" sublist belongs to its smoother: the
/// "chebyshev: ..." keys of the default list are dropped when the merged smoother is not
/// Chebyshev (Ifpack2 rejects keys of another smoother).
Teuchos::ParameterList merged(const Teuchos::ParameterList& base,
                              const Teuchos::ParameterList* over) {
  Teuchos::ParameterList m = base;
  if (over) m.setParameters(*over);
  if (m.isSublist("smoother: params") &&
      m.get<std::string>("smoother: type", "RELAXATION") != "CHEBYSHEV") {
    Teuchos::ParameterList& sp = m.sublist("smoother: params");
    std::vector<std::string> cheb;
    for (auto it = sp.begin(); it != sp.end(); ++it)
      if (sp.name(it).rfind("chebyshev: ", 0) == 0) cheb.push_back(sp.name(it));
    for (const auto& k : cheb) sp.remove(k);
  }
  return m;
}

/// MueLu's list for a system: solver/MueLu, then solver/MueLu_solids if it couples solids, then
/// solver/MueLu_one_level if it has no coarser level and several ranks.
Teuchos::ParameterList muelu_list(const SolverSettings& s, bool with_solids, long long unknowns,
                                  int ranks) {
  Teuchos::ParameterList m = merged(s.muelu, with_solids ? &s.muelu_solids : nullptr);
  if (ranks > 1 && unknowns <= m.get<int>("coarse: max size", 2000))
    m = merged(m, &s.muelu_one_level);
  return m;
}

/// Trilinos' own lists of valid parameters check the case's lists before the first solve:
/// Belos' valid parameters of PseudoBlockCG and MueLu's master list (top level; the smoother and
/// coarse sublists are checked by Ifpack2/Amesos2 when the hierarchy is built).
void validate(const SolverSettings& s) {
  const std::vector<std::pair<const char*, Teuchos::ParameterList>> lists = {
      {"solver/MueLu", merged(s.muelu, nullptr)},
      {"solver/MueLu_solids", merged(s.muelu, &s.muelu_solids)},
      {"solver/MueLu_one_level", merged(s.muelu, &s.muelu_one_level)}};
  for (const auto& [key, list] : lists) {
    Teuchos::ParameterList top = list;
    std::vector<std::string> levels;  // MueLu's "level N" sublists: not in the master list
    for (auto it = top.begin(); it != top.end(); ++it)
      if (top.name(it).rfind("level ", 0) == 0) levels.push_back(top.name(it));
    for (const auto& l : levels) top.remove(l);
    try {
      top.validateParameters(*MueLu::MasterList::List(), 0);
    } catch (const std::exception& e) {
      throw core::InputError(std::string(key) + ": MueLu rejected the settings: " + e.what());
    }
  }
  try {
    Belos::PseudoBlockCGSolMgr<double, MV, OP> cg;
    s.belos.validateParameters(*cg.getValidParameters(), 0);
  } catch (const std::exception& e) {
    throw core::InputError(std::string("solver/Belos: Belos rejected the settings: ") + e.what());
  }
}

SolverSettings settings_from(const core::Params& params) {
  SolverSettings s;
  s.tolerance = params.real("solver/tolerance");
  s.max_iterations = static_cast<int>(params.integer("solver/max_iterations"));
  s.rebalance = params.boolean("solver/rebalance");
  s.belos = params.teuchos("solver/Belos");
  s.muelu = params.teuchos("solver/MueLu");
  s.muelu_solids = params.teuchos("solver/MueLu_solids");
  s.muelu_one_level = params.teuchos("solver/MueLu_one_level");
  validate(s);
  return s;
}

}  // namespace

struct PressureSolver::Impl {
  const grid::Decomposition& d;
  grid::Halo halo;
  SolverSettings settings;
  /// The couplings of the last assembly, joined, with the cells that are not fluid left out:
  /// the rows a_{s,c} of the matrix, from which solid_loads() computes J p.
  mutable std::map<std::int64_t, SolidCoupling> solid_rows;
  Impl(const grid::Decomposition& dec, const core::Params& params)
      : d(dec), halo(dec), settings(settings_from(params)) {}
};

PressureSolver::PressureSolver(const grid::Decomposition& d, const core::Params& params)
    : impl_(std::make_unique<Impl>(d, params)) {}
PressureSolver::~PressureSolver() = default;

AssembledSystem PressureSolver::assemble(const CellStates& cells, const Apertures& E,
                                         const grid::FaceField& u, const grid::FaceField& w,
                                         const std::vector<SolidCoupling>& couplings, double dt,
                                         const FluidConfig& cfg, const SurfaceFractions* surface,
                                         const grid::CellField* source) const {
  core::ScopedTimer timer("fluid: pressure assembly");
  const grid::Decomposition& d = impl_->d;
  const grid::GridSpec& g = d.spec();
  const core::IndexBox own = d.owned_cells();
  AssembledSystem sys;
  grid::GridArray<int> row_of(d, grid::Stagger::Cell, -1);
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i)
      if (cells(i, k) == kFluid) {
        row_of(i, k) = static_cast<int>(sys.rows.size());
        sys.rows.push_back(g.cell_gid(i, k));
      }
  sys.entries.resize(sys.rows.size());
  sys.rhs.assign(sys.rows.size(), 0.0);
  grid::CellField D(d, grid::Stagger::Cell, 0.0);
  divergence(u, w, E, cells, D);

  const double s = dt / (cfg.rho * g.h);
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      const int r = row_of(i, k);
      if (r < 0) continue;
      auto& row = sys.entries[static_cast<std::size_t>(r)];
      double diag = 0.0;
      const struct {
        double E, theta;
        int i, k;
      } faces[4] = {{E.E_x(i, k), surface ? surface->theta_x(i, k) : 1.0, i - 1, k},
                    {E.E_x(i + 1, k), surface ? surface->theta_x(i + 1, k) : 1.0, i + 1, k},
                    {E.E_z(i, k), surface ? surface->theta_z(i, k) : 1.0, i, k - 1},
                    {E.E_z(i, k + 1), surface ? surface->theta_z(i, k + 1) : 1.0, i, k + 1}};
      for (const auto& f : faces) {
        if (f.E <= 0.0 || f.i < 0 || f.k < 0 || f.i >= g.nx || f.k >= g.nz) continue;
        const signed char nb = cells(f.i, f.k);
        if (nb == kSolid) continue;
        // -L_E: diagonal sum_f E_f dt/(rho h); fluid neighbour -E_f dt/(rho h); air: p = 0
        // at theta h (theta = 1: the air cell's centre), diagonal E_f dt/(rho h theta)
        if (nb == kFluid) {
          diag += f.E * s;
          row.emplace_back(g.cell_gid(f.i, f.k), -f.E * s);
        } else {
          diag += f.E * s / f.theta;
        }
      }
      row.emplace_back(g.cell_gid(i, k), diag);
      // b = -D(u~)  (eq. 5 with the sign of -L_E)
      sys.rhs[static_cast<std::size_t>(r)] = -D(i, k) + (source ? (*source)(i, k) : 0.0);
    }

  const auto joined = detail::gather_couplings(couplings, d.comm());
  sys.with_solids = !joined.empty();
  impl_->solid_rows.clear();
  if (!joined.empty()) {
    // Which coupling cells are fluid: each owner answers for its cells, summed over ranks.
    std::vector<double> fluid_flag;
    for (const auto& [id, sc] : joined)
      for (long long c : sc.cells) {
        const int i = static_cast<int>(c % g.nx), k = static_cast<int>(c / g.nx);
        const bool inside = c >= 0 && k < g.nz;
        fluid_flag.push_back(inside && own.contains(i, k) && cells(i, k) == kFluid ? 1.0 : 0.0);
      }
    d.comm().sum_in_place(fluid_flag);
    std::size_t flag = 0;
    for (const auto& [id, sc] : joined) {
      SolidCoupling& kept = impl_->solid_rows[id];
      kept = sc;
      kept.cells.clear(), kept.a.clear();
      for (std::size_t a = 0; a < sc.cells.size(); ++a, ++flag)
        if (fluid_flag[flag] != 0.0) kept.cells.push_back(sc.cells[a]), kept.a.push_back(sc.a[a]);
    }
    std::size_t flag0 = 0;
    for (const auto& [id, sc] : joined) {
      const std::array<double, 3> Minv{1.0 / sc.mass, 1.0 / sc.mass, 1.0 / sc.inertia};
      const std::size_t n = sc.cells.size();
      for (std::size_t a = 0; a < n; ++a) {
        if (fluid_flag[flag0 + a] == 0.0) continue;
        const long long c1 = sc.cells[a];
        const int i = static_cast<int>(c1 % g.nx), k = static_cast<int>(c1 / g.nx);
        if (!own.contains(i, k)) continue;
        const auto r = static_cast<std::size_t>(row_of(i, k));
        const auto& a1 = sc.a[a];
        // b_c += a_{s,c} . V*_s
        sys.rhs[r] += a1[0] * sc.v_star[0] + a1[1] * sc.v_star[1] + a1[2] * sc.v_star[2];
        for (std::size_t b = 0; b < n; ++b) {
          if (fluid_flag[flag0 + b] == 0.0) continue;
          const auto& a2 = sc.a[b];
          // dt A_s M_s^-1 A_s^T, entry (c1, c2) = dt a_{c1} . M^-1 a_{c2}
          const double v =
              dt * (a1[0] * Minv[0] * a2[0] + a1[1] * Minv[1] * a2[1] + a1[2] * Minv[2] * a2[2]);
          sys.entries[r].emplace_back(sc.cells[b], v);
        }
      }
      flag0 += n;
    }
  }
  // Sorted by column, duplicates summed.
  for (auto& row : sys.entries) {
    std::sort(row.begin(), row.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    std::size_t m = 0;
    for (std::size_t n = 0; n < row.size(); ++n) {
      if (m > 0 && row[m - 1].first == row[n].first)
        row[m - 1].second += row[n].second;
      else
        row[m++] = row[n];
    }
    row.resize(m);
  }
  return sys;
}

namespace {

/// Matrix rows with global (contiguous) numbers, as moved between ranks.
struct Rows {
  std::vector<GO> gid;
  std::vector<std::size_t> ptr;
  std::vector<GO> col;
  std::vector<double> val, rhs, x, cx, cz;
};

int owner_in(const std::vector<long long>& first, long long gid) {
  return static_cast<int>(std::upper_bound(first.begin(), first.end(), gid) - first.begin()) - 1;
}

/// Sends every row to the rank whose range [first[q], first[q+1]) holds its number. Rows arrive
/// in increasing number (ranges are contiguous and sent in order).
Rows exchange_rows(const Rows& in, const std::vector<long long>& first, MPI_Comm comm) {
  int P = 0;
  MPI_Comm_size(comm, &P);
  std::vector<std::vector<double>> out(static_cast<std::size_t>(P));
  for (std::size_t r = 0; r < in.gid.size(); ++r) {
    auto& b = out[static_cast<std::size_t>(owner_in(first, in.gid[r]))];
    const std::size_t n = in.ptr[r + 1] - in.ptr[r];
    b.insert(b.end(), {static_cast<double>(in.gid[r]), static_cast<double>(n), in.rhs[r], in.x[r],
                       in.cx[r], in.cz[r]});
    for (std::size_t m = in.ptr[r]; m < in.ptr[r + 1]; ++m)
      b.insert(b.end(), {static_cast<double>(in.col[m]), in.val[m]});
  }
  std::vector<int> send_n(static_cast<std::size_t>(P)), recv_n(static_cast<std::size_t>(P));
  std::vector<int> send_at(static_cast<std::size_t>(P)), recv_at(static_cast<std::size_t>(P));
  std::vector<double> send;
  for (int q = 0; q < P; ++q) {
    send_at[static_cast<std::size_t>(q)] = static_cast<int>(send.size());
    send_n[static_cast<std::size_t>(q)] = static_cast<int>(out[static_cast<std::size_t>(q)].size());
    send.insert(send.end(), out[static_cast<std::size_t>(q)].begin(),
                out[static_cast<std::size_t>(q)].end());
  }
  MPI_Alltoall(send_n.data(), 1, MPI_INT, recv_n.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int q = 0; q < P; ++q)
    recv_at[static_cast<std::size_t>(q)] = total, total += recv_n[static_cast<std::size_t>(q)];
  std::vector<double> recv(static_cast<std::size_t>(total));
  MPI_Alltoallv(send.data(), send_n.data(), send_at.data(), MPI_DOUBLE, recv.data(), recv_n.data(),
                recv_at.data(), MPI_DOUBLE, comm);
  Rows rows;
  rows.ptr.push_back(0);
  for (std::size_t p = 0; p < recv.size();) {
    rows.gid.push_back(static_cast<GO>(recv[p]));
    const auto n = static_cast<std::size_t>(recv[p + 1]);
    rows.rhs.push_back(recv[p + 2]);
    rows.x.push_back(recv[p + 3]);
    rows.cx.push_back(recv[p + 4]);
    rows.cz.push_back(recv[p + 5]);
    p += 6;
    for (std::size_t m = 0; m < n; ++m, p += 2) {
      rows.col.push_back(static_cast<GO>(recv[p]));
      rows.val.push_back(recv[p + 1]);
    }
    rows.ptr.push_back(rows.col.size());
  }
  return rows;
}

/// The values of the rows numbered `gid` (held here) sent back to the ranks whose ranges
/// `first` hold them; returns this rank's values in increasing number.
std::vector<double> return_values(const std::vector<GO>& gid, const std::vector<double>& v,
                                  const std::vector<long long>& first, MPI_Comm comm) {
  Rows r;
  r.gid = gid;
  r.ptr.assign(gid.size() + 1, 0);
  r.rhs = v;
  r.x = r.cx = r.cz = std::vector<double>(gid.size(), 0.0);
  const Rows back = exchange_rows(r, first, comm);
  return back.rhs;
}

/// The CrsMatrix of `rows` (numbers of `map`, contiguous): column map = own rows, then the
/// other columns in increasing number.
RCP<Matrix> build_matrix(const Rows& rows, const RCP<const Map>& map,
                         const RCP<const Teuchos::Comm<int>>& tcomm) {
  const GO first = rows.gid.empty() ? 0 : rows.gid.front();
  const auto n = static_cast<GO>(rows.gid.size());
  std::vector<GO> remote;
  for (GO c : rows.col)
    if (c < first || c >= first + n) remote.push_back(c);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<GO> col_gids(rows.gid.begin(), rows.gid.end());
  col_gids.insert(col_gids.end(), remote.begin(), remote.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  RCP<const Map> col_map = rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(col_gids.data(), col_gids.size()), 0, tcomm));
  Teuchos::ArrayRCP<std::size_t> row_ptr(rows.gid.size() + 1);
  Teuchos::ArrayRCP<LO> col_idx(rows.col.size());
  Teuchos::ArrayRCP<double> vals(rows.col.size());
  std::vector<std::pair<LO, double>> tmp;
  row_ptr[0] = 0;
  for (std::size_t r = 0; r < rows.gid.size(); ++r) {
    tmp.clear();
    for (std::size_t m = rows.ptr[r]; m < rows.ptr[r + 1]; ++m) {
      const GO c = rows.col[m];
      const LO lid = c >= first && c < first + n
                         ? static_cast<LO>(c - first)
                         : static_cast<LO>(n + (std::lower_bound(remote.begin(), remote.end(), c) -
                                                remote.begin()));
      tmp.emplace_back(lid, rows.val[m]);
    }
    std::sort(tmp.begin(), tmp.end());
    std::size_t m = rows.ptr[r];
    for (const auto& [lid, v] : tmp) col_idx[m] = lid, vals[m] = v, ++m;
    row_ptr[r + 1] = rows.ptr[r + 1];
  }
  RCP<Matrix> A = rcp(new Matrix(map, col_map, row_ptr, col_idx, vals));
  A->fillComplete(map, map);
  return A;
}

SolveStats run_solver(const grid::Decomposition& d, const SolverSettings& settings,
                      const AssembledSystem& sys, std::vector<double>& x) {
  const auto t0 = std::chrono::steady_clock::now();
  SolveStats stats;
  if (!Tpetra::isInitialized())
    throw core::SolverError(
        "the pressure solver needs Tpetra initialised: create a fluid::LinearAlgebraScope in "
        "main()");
  const core::Comm& comm = d.comm();
  const grid::GridSpec& g = d.spec();
  const auto n_local = static_cast<long long>(sys.rows.size());
  stats.unknowns = comm.sum(n_local);
  x.resize(sys.rows.size(), 0.0);
  double b2 = 0.0;
  for (double v : sys.rhs) b2 += v * v;
  const double b_norm = std::sqrt(comm.sum(b2));
  if (stats.unknowns == 0 || b_norm == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    return stats;
  }

  RCP<const Teuchos::Comm<int>> tcomm = rcp(new Teuchos::MpiComm<int>(comm.raw()));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  // Unknowns are numbered contiguously over ranks (rank offset + local index): Amesos2's coarse
  // solve was measured to give wrong answers on maps of the non-contiguous cell ids.
  std::vector<GO> cell_ids(sys.rows.begin(), sys.rows.end());
  RCP<const Map> cell_map = rcp(
      new Map(invalid, Teuchos::ArrayView<const GO>(cell_ids.data(), cell_ids.size()), 0, tcomm));
  RCP<const Map> row_map =
      rcp(new Map(static_cast<Tpetra::global_size_t>(stats.unknowns), sys.rows.size(), 0, tcomm));
  const std::vector<double> offsets =
      comm.all_gather({static_cast<double>(comm.exclusive_scan(n_local))});
  std::vector<GO> row_gids(sys.rows.size());
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    row_gids[r] = row_map->getGlobalElement(static_cast<LO>(r));

  // Column numbers: owned cells by local index, other cells through their owner.
  grid::GridArray<int> local_of(d, grid::Stagger::Cell, -1);
  const core::IndexBox own = d.owned_cells();
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    local_of(static_cast<int>(sys.rows[r] % g.nx), static_cast<int>(sys.rows[r] / g.nx)) =
        static_cast<int>(r);
  auto owned_lid = [&](long long gid) {
    const int i = static_cast<int>(gid % g.nx), k = static_cast<int>(gid / g.nx);
    return own.contains(i, k) ? local_of(i, k) : -1;
  };
  std::vector<GO> remote;
  for (const auto& row : sys.entries)
    for (const auto& [c, v] : row)
      if (owned_lid(c) < 0) remote.push_back(c);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<GO> remote_gid(remote.size());
  {
    // Owner and local index of every remote cell id give its contiguous number.
    Teuchos::Array<int> pids(remote.size());
    Teuchos::Array<LO> lids(remote.size());
    cell_map->getRemoteIndexList(Teuchos::ArrayView<const GO>(remote.data(), remote.size()), pids(),
                                 lids());
    for (std::size_t n = 0; n < remote.size(); ++n) {
      if (pids[n] < 0)
        throw core::SolverError("pressure matrix column of cell " + std::to_string(remote[n]) +
                                " is not a fluid cell on any rank");
      remote_gid[n] = static_cast<GO>(offsets[static_cast<std::size_t>(pids[n])]) + lids[n];
    }
  }
  Rows rows;
  rows.ptr.push_back(0);
  for (std::size_t r = 0; r < sys.rows.size(); ++r) {
    rows.gid.push_back(row_gids[r]);
    for (const auto& [c, v] : sys.entries[r]) {
      const int lid = owned_lid(c);
      rows.col.push_back(
          lid >= 0 ? row_gids[static_cast<std::size_t>(lid)]
                   : remote_gid[static_cast<std::size_t>(
                         std::lower_bound(remote.begin(), remote.end(), c) - remote.begin())]);
      rows.val.push_back(v);
    }
    rows.ptr.push_back(rows.col.size());
    rows.rhs.push_back(sys.rhs[r]);
    rows.x.push_back(x[r]);
    const auto c = g.position(grid::Stagger::Cell, static_cast<int>(sys.rows[r] % g.nx),
                              static_cast<int>(sys.rows[r] / g.nx));
    rows.cx.push_back(c.x);
    rows.cz.push_back(c.z);
  }

  // The grid's blocks hold unequal numbers of fluid cells (a dam break leaves whole blocks
  // dry): the rows are moved to an equal split of the same numbering, which keeps each rank's
  // rows a few contiguous strips of cells.
  const int P = comm.size();
  std::vector<long long> grid_first(static_cast<std::size_t>(P) + 1), solve_first = grid_first;
  for (int q = 0; q < P; ++q)
    grid_first[static_cast<std::size_t>(q)] =
        static_cast<long long>(offsets[static_cast<std::size_t>(q)]);
  grid_first[static_cast<std::size_t>(P)] = stats.unknowns;
  const bool rebalance = settings.rebalance && P > 1;
  for (int q = 0; q <= P; ++q)
    solve_first[static_cast<std::size_t>(q)] =
        rebalance ? stats.unknowns * q / P : grid_first[static_cast<std::size_t>(q)];
  if (rebalance) rows = exchange_rows(rows, solve_first, comm.raw());

  RCP<const Map> solve_map =
      rcp(new Map(static_cast<Tpetra::global_size_t>(stats.unknowns), rows.gid.size(), 0, tcomm));
  RCP<Matrix> A = build_matrix(rows, solve_map, tcomm);
  row_map = solve_map;
  RCP<MV> X = rcp(new MV(row_map, 1)), B = rcp(new MV(row_map, 1));
  RCP<MV> coords = rcp(new MV(row_map, 2));
  {
    auto xv = X->getDataNonConst(0);
    auto bv = B->getDataNonConst(0);
    auto cx = coords->getDataNonConst(0);
    auto cz = coords->getDataNonConst(1);
    for (std::size_t r = 0; r < rows.gid.size(); ++r)
      xv[r] = rows.x[r], bv[r] = rows.rhs[r], cx[r] = rows.cx[r], cz[r] = rows.cz[r];
  }

  Teuchos::ParameterList muelu = muelu_list(settings, sys.with_solids, stats.unknowns, comm.size());
  muelu.sublist("user data").set("Coordinates", coords);
  RCP<OP> prec;
  {
    core::ScopedTimer timer("fluid: pressure preconditioner");
    try {
      prec = MueLu::CreateTpetraPreconditioner(RCP<OP>(A), muelu);
    } catch (const Teuchos::Exceptions::InvalidParameter& e) {
      throw core::InputError(std::string("solver/MueLu: MueLu rejected the settings: ") + e.what());
    }
  }
  stats.setup_seconds = seconds_since(t0);

  const auto t1 = std::chrono::steady_clock::now();
  auto true_residual = [&]() {
    MV R(row_map, 1);
    A->apply(*X, R);
    R.update(1.0, *B, -1.0);
    Teuchos::Array<double> norm(1);
    R.norm2(norm());
    return norm[0] / b_norm;
  };
  {
    core::ScopedTimer timer("fluid: pressure solve");
    auto problem = rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
    problem->setLeftPrec(prec);
    problem->setProblem();
    auto belos = rcp(new Teuchos::ParameterList(settings.belos));
    belos->set("Convergence Tolerance", settings.tolerance);
    belos->set("Maximum Iterations", settings.max_iterations);
    Belos::PseudoBlockCGSolMgr<double, MV, OP> solver(problem, belos);
    // The implicit residual may drift from the true one; one restart from the reached x.
    for (int attempt = 0; attempt < 2; ++attempt) {
      solver.solve();
      stats.iterations += solver.getNumIters();
      stats.relative_residual = true_residual();
      if (stats.relative_residual <= settings.tolerance) break;
      problem->setProblem();
      solver.reset(Belos::Problem);
    }
  }
  stats.solve_seconds = seconds_since(t1);
  {
    auto xv = X->getData(0);
    std::vector<double> solved(xv.begin(), xv.end());
    if (rebalance) solved = return_values(rows.gid, solved, grid_first, comm.raw());
    for (std::size_t r = 0; r < sys.rows.size(); ++r) x[r] = solved[r];
  }
  if (!(stats.relative_residual <= settings.tolerance)) {
    std::ostringstream msg;
    msg << "pressure solve did not converge: relative true residual " << stats.relative_residual
        << " after " << stats.iterations << " iterations, solver/tolerance = " << settings.tolerance
        << " (solver/max_iterations = " << settings.max_iterations << ")";
    throw core::SolverError(msg.str());
  }
  return stats;
}

}  // namespace

SolveStats PressureSolver::solve(const CellStates& cells, const Apertures& E,
                                 const grid::FaceField& u, const grid::FaceField& w,
                                 const std::vector<SolidCoupling>& couplings, double dt,
                                 const FluidConfig& cfg, grid::CellField& p,
                                 const SurfaceFractions* surface, const grid::CellField* source) {
  const auto t0 = std::chrono::steady_clock::now();
  const AssembledSystem sys = assemble(cells, E, u, w, couplings, dt, cfg, surface, source);
  const double assembly = seconds_since(t0);
  const grid::GridSpec& g = impl_->d.spec();
  std::vector<double> x(sys.rows.size());
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    x[r] = p(static_cast<int>(sys.rows[r] % g.nx), static_cast<int>(sys.rows[r] / g.nx));
  SolveStats stats = run_solver(impl_->d, impl_->settings, sys, x);
  stats.setup_seconds += assembly;
  const core::IndexBox own = impl_->d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) p(i, k) = 0.0;
  for (std::size_t r = 0; r < sys.rows.size(); ++r)
    p(static_cast<int>(sys.rows[r] % g.nx), static_cast<int>(sys.rows[r] / g.nx)) = x[r];
  impl_->halo.forward(p);
  return stats;
}

std::vector<core::SolidLoads> PressureSolver::solid_loads(const grid::CellField& p) const {
  return detail::coupling_loads(impl_->solid_rows, p, impl_->d);
}

SolveStats solve_system(const grid::Decomposition& d, const core::Params& params,
                        const AssembledSystem& system, std::vector<double>& x) {
  return run_solver(d, settings_from(params), system, x);
}

struct LinearAlgebraScope::Impl {
  Tpetra::ScopeGuard guard;
  Impl(int* argc, char*** argv) : guard(argc, argv) {}
};
LinearAlgebraScope::LinearAlgebraScope(int* argc, char*** argv)
    : impl_(std::make_unique<Impl>(argc, argv)) {}
LinearAlgebraScope::~LinearAlgebraScope() = default;

}  // namespace picdem::fluid

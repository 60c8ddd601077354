// Ownership and the communication verbs of the DEM: exchange (migration), borders (ghost lists),
// forward (ghost refresh), gather (output), plus the neighbour list and checkpoint arrays.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "picdem/core/timer.hpp"
#include "picdem/dem/dem_solver.hpp"

namespace picdem::dem {

using core::SolidState;

namespace {

double box_distance(const core::Box2& b, const Vec2& p) {
  const double dx = std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x});
  const double dz = std::max({b.lo.z - p.z, 0.0, p.z - b.hi.z});
  return std::hypot(dx, dz);
}

constexpr int state_doubles = 10;  // id, shape, mass, inertia, x, z, theta, u, w, omega

void pack_state(const SolidState& s, std::vector<double>& buf) {
  buf.insert(buf.end(), {static_cast<double>(s.id), static_cast<double>(s.shape), s.mass, s.inertia,
                         s.x.x, s.x.z, s.theta, s.v.x, s.v.z, s.omega});
}

SolidState unpack_state(const double* p) {
  SolidState s;
  s.id = static_cast<std::int64_t>(p[0]);
  s.shape = static_cast<int>(p[1]);
  s.mass = p[2];
  s.inertia = p[3];
  s.x = {p[4], p[5]};
  s.theta = p[6];
  s.v = {p[7], p[8]};
  s.omega = p[9];
  return s;
}

/// Sends buffers[r] to rank r; returns what every rank sent here, in rank order, and the count
/// received from each rank. With `known_in` (the counts each rank sends here, known from an
/// earlier exchange) the counts are not exchanged first: one collective instead of two.
std::vector<double> all_to_all(const core::Comm& comm, const std::vector<std::vector<double>>& out,
                               std::vector<int>* counts_in = nullptr,
                               const std::vector<int>* known_in = nullptr) {
  const int p = comm.size();
  std::vector<int> sc(p), rc(p), sd(p, 0), rd(p, 0);
  for (int r = 0; r < p; ++r) sc[r] = static_cast<int>(out[static_cast<std::size_t>(r)].size());
  if (known_in)
    rc = *known_in;
  else
    MPI_Alltoall(sc.data(), 1, MPI_INT, rc.data(), 1, MPI_INT, comm.raw());
  for (int r = 1; r < p; ++r) sd[r] = sd[r - 1] + sc[r - 1], rd[r] = rd[r - 1] + rc[r - 1];
  std::vector<double> send(static_cast<std::size_t>(sd[p - 1] + sc[p - 1]));
  for (int r = 0; r < p; ++r)
    std::copy(out[static_cast<std::size_t>(r)].begin(), out[static_cast<std::size_t>(r)].end(),
              send.begin() + sd[r]);
  std::vector<double> in(static_cast<std::size_t>(rd[p - 1] + rc[p - 1]));
  MPI_Alltoallv(send.data(), sc.data(), sd.data(), MPI_DOUBLE, in.data(), rc.data(), rd.data(),
                MPI_DOUBLE, comm.raw());
  if (counts_in) *counts_in = rc;
  return in;
}

}  // namespace

int DemSolver::owner_of(const Vec2& x) const {
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    const auto& b = regions_[r];
    if (x.x >= b.lo.x && x.x < b.hi.x && x.z >= b.lo.z && x.z < b.hi.z) return static_cast<int>(r);
  }
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    const double d = box_distance(regions_[r], x);
    if (d < best_d) best_d = d, best = static_cast<int>(r);
  }
  return best;
}

void DemSolver::sort_owned() {
  std::vector<std::size_t> order(owned_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return owned_[a].id < owned_[b].id; });
  std::vector<SolidState> o;
  std::vector<Springs> sp;
  std::vector<Vec2> vs;
  std::vector<double> ws;
  for (std::size_t n : order) {
    o.push_back(owned_[n]);
    sp.push_back(std::move(springs_[n]));
    vs.push_back(v_start_[n]);
    ws.push_back(omega_start_[n]);
  }
  owned_.swap(o);
  springs_.swap(sp);
  v_start_.swap(vs);
  omega_start_.swap(ws);
}

// exchange: every owned solid whose centre left this rank's region moves to its new owner with
// its contact history and its start-of-step velocities.
void DemSolver::exchange() {
  if (comm_.size() == 1) return;
  const int me = comm_.rank();
  std::vector<std::vector<double>> out(static_cast<std::size_t>(comm_.size()));
  std::size_t kept = 0;
  for (std::size_t i = 0; i < owned_.size(); ++i) {
    const int r = owner_of(owned_[i].x);
    if (r == me) {
      if (kept != i) {  // (a self-move would empty the springs)
        owned_[kept] = owned_[i];
        springs_[kept] = std::move(springs_[i]);
        v_start_[kept] = v_start_[i];
        omega_start_[kept] = omega_start_[i];
      }
      ++kept;
      continue;
    }
    auto& buf = out[static_cast<std::size_t>(r)];
    pack_state(owned_[i], buf);
    buf.insert(buf.end(), {v_start_[i].x, v_start_[i].z, omega_start_[i],
                           static_cast<double>(springs_[i].size())});
    for (const auto& [key, s] : springs_[i]) buf.insert(buf.end(), {static_cast<double>(key), s});
  }
  owned_.resize(kept);
  springs_.resize(kept);
  v_start_.resize(kept);
  omega_start_.resize(kept);
  const std::vector<double> in = all_to_all(comm_, out);
  for (std::size_t p = 0; p < in.size();) {
    owned_.push_back(unpack_state(&in[p]));
    p += state_doubles;
    v_start_.push_back({in[p], in[p + 1]});
    omega_start_.push_back(in[p + 2]);
    const auto n = static_cast<std::size_t>(in[p + 3]);
    p += 4;
    Springs sp;
    for (std::size_t e = 0; e < n; ++e, p += 2)
      sp.emplace_back(static_cast<std::int64_t>(in[p]), in[p + 1]);
    springs_.push_back(std::move(sp));
  }
  sort_owned();
}

// borders: every owned solid within contact reach (plus the skin) of another rank's region is
// sent there as a ghost; the send lists are kept for forward() until the next rebuild.
void DemSolver::borders() {
  ghosts_.clear();
  for (auto& l : send_list_) l.clear();
  if (comm_.size() == 1) return;
  const int me = comm_.rank();
  const double reach = max_radius_ + cfg_.gap() + skin_;
  std::vector<std::vector<double>> out(static_cast<std::size_t>(comm_.size()));
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    if (static_cast<int>(r) == me) continue;
    for (std::size_t i = 0; i < owned_.size(); ++i) {
      const double R = shapes_[static_cast<std::size_t>(owned_[i].shape)].radius;
      if (box_distance(regions_[r], owned_[i].x) < R + reach) {
        send_list_[r].push_back(static_cast<int>(i));
        pack_state(owned_[i], out[r]);
      }
    }
  }
  const std::vector<double> in = all_to_all(comm_, out, &recv_count_);
  for (std::size_t p = 0; p < in.size(); p += state_doubles)
    ghosts_.push_back(unpack_state(&in[p]));
}

// forward: ghost poses and velocities refreshed from their owners (same lists as borders()).
void DemSolver::forward() {
  if (comm_.size() == 1) return;
  core::ScopedTimer timer("dem: forward");
  std::vector<std::vector<double>> out(static_cast<std::size_t>(comm_.size()));
  for (std::size_t r = 0; r < send_list_.size(); ++r)
    for (int i : send_list_[r]) {
      const SolidState& s = owned_[static_cast<std::size_t>(i)];
      out[r].insert(out[r].end(), {s.x.x, s.x.z, s.theta, s.v.x, s.v.z, s.omega});
    }
  // the ghosts of each rank are those of borders(): 6 of its state_doubles per ghost
  std::vector<int> in_count(recv_count_.size());
  for (std::size_t r = 0; r < in_count.size(); ++r)
    in_count[r] = recv_count_[r] / state_doubles * 6;
  const std::vector<double> in = all_to_all(comm_, out, nullptr, &in_count);
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const double* p = &in[6 * g];
    ghosts_[g].x = {p[0], p[1]};
    ghosts_[g].theta = p[2];
    ghosts_[g].v = {p[3], p[4]};
    ghosts_[g].omega = p[5];
  }
}

namespace {

/// Solids sorted into square cells of at least `cell` over their bounding box (the cell grows
/// while there are more than 4 cells per solid + 64), by a counting sort.
struct CellList {
  Vec2 lo;
  double cell = 0.0;
  long long nx = 0, nz = 0;
  std::vector<int> start, order;  // solids of cell c: order[start[c] .. start[c + 1])

  void cell_of(const Vec2& x, long long& ci, long long& ck) const {
    if (!std::isfinite(x.x) || !std::isfinite(x.z)) {
      ci = ck = 0;
      return;
    }
    ci = std::min(nx - 1, static_cast<long long>((x.x - lo.x) / cell));
    ck = std::min(nz - 1, static_cast<long long>((x.z - lo.z) / cell));
  }
};

template <class At>
CellList make_cell_list(const At& at, std::size_t n_all, double cell) {
  CellList cl;
  // the box of the solids with a finite position (a blown-up one, left in cell 0, meets nothing:
  // its distances compare false; the step's check stops the run on every rank)
  auto finite = [](const Vec2& x) { return std::isfinite(x.x) && std::isfinite(x.z); };
  Vec2 lo{0.0, 0.0}, hi{0.0, 0.0};
  bool first = true;
  for (std::size_t j = 0; j < n_all; ++j) {
    const Vec2& x = at(j).x;
    if (!finite(x)) continue;
    lo = first ? x : Vec2{std::min(lo.x, x.x), std::min(lo.z, x.z)};
    hi = first ? x : Vec2{std::max(hi.x, x.x), std::max(hi.z, x.z)};
    first = false;
  }
  // the counts in double: a blown-up solid far away must not overflow them (exact below 2^53,
  // so the same cells as in integers otherwise)
  auto count = [](double span, double c) { return std::floor(span / c) + 1.0; };
  while (count(hi.x - lo.x, cell) * count(hi.z - lo.z, cell) >
         4.0 * static_cast<double>(n_all) + 64)
    cell *= 2.0;
  const auto nx = static_cast<long long>(count(hi.x - lo.x, cell));
  const auto nz = static_cast<long long>(count(hi.z - lo.z, cell));
  cl.lo = lo, cl.cell = cell, cl.nx = nx, cl.nz = nz;
  // counting sort of the solids into cells
  cl.start.assign(static_cast<std::size_t>(nx * nz + 1), 0);
  cl.order.resize(n_all);
  std::vector<long long> cell_id(n_all);
  for (std::size_t j = 0; j < n_all; ++j) {
    long long ci, ck;
    cl.cell_of(at(j).x, ci, ck);
    cell_id[j] = ck * nx + ci;
    ++cl.start[static_cast<std::size_t>(cell_id[j]) + 1];
  }
  std::partial_sum(cl.start.begin(), cl.start.end(), cl.start.begin());
  std::vector<int> fill(cl.start.begin(), cl.start.end() - 1);
  for (std::size_t j = 0; j < n_all; ++j)
    cl.order[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_id[j])]++)] =
        static_cast<int>(j);
  return cl;
}

}  // namespace

// Cell list over owned + ghost solids; partners of each owned solid within contact reach plus
// the skin, sorted by global id (the summation order of eqs. 16-17).
void DemSolver::build_neighbours() {
  core::ScopedTimer timer("dem: neighbour list");
  const std::size_t n_owned = owned_.size(), n_all = n_owned + ghosts_.size();
  auto at = [&](std::size_t j) -> const SolidState& {
    return j < n_owned ? owned_[j] : ghosts_[j - n_owned];
  };
  nbr_start_.assign(n_owned + 1, 0);
  nbr_.clear();
  mirror_.clear();
  obs_start_.assign(n_owned + 1, 0);
  obs_.clear();
  if (n_all == 0) return;
  const double extra = cfg_.gap() + skin_;
  const CellList cl = make_cell_list(at, n_all, 2.0 * max_radius_ + extra);
  std::vector<std::pair<std::int64_t, int>> cand;
  for (std::size_t i = 0; i < n_owned; ++i) {
    const SolidState& s = owned_[i];
    const double Ri = shapes_[static_cast<std::size_t>(s.shape)].radius;
    long long ci, ck;
    cl.cell_of(s.x, ci, ck);
    cand.clear();
    for (long long k = std::max(0LL, ck - 1); k <= std::min(cl.nz - 1, ck + 1); ++k)
      for (long long c = std::max(0LL, ci - 1); c <= std::min(cl.nx - 1, ci + 1); ++c) {
        const auto cid = static_cast<std::size_t>(k * cl.nx + c);
        for (int q = cl.start[cid]; q < cl.start[cid + 1]; ++q) {
          const auto j = static_cast<std::size_t>(cl.order[static_cast<std::size_t>(q)]);
          if (j == i) continue;
          const SolidState& p = at(j);
          const double Rj = shapes_[static_cast<std::size_t>(p.shape)].radius;
          const double reach = Ri + Rj + extra;
          if (core::norm2(p.x - s.x) < reach * reach) cand.emplace_back(p.id, static_cast<int>(j));
        }
      }
    std::sort(cand.begin(), cand.end());
    for (const auto& c : cand) nbr_.push_back(c.second);
    nbr_start_[i + 1] = static_cast<int>(nbr_.size());
  }
  // Each owned pair is evaluated once, at the entry of its lower local index; the other entry
  // reads that result (collision_forces). The reach above is symmetric, so j's list holds i
  // whenever i's holds j; a missing mirror would only mean evaluating the pair twice.
  mirror_.assign(nbr_.size(), -1);
  for (std::size_t i = 0; i < n_owned; ++i)
    for (int n = nbr_start_[i]; n < nbr_start_[i + 1]; ++n) {
      const int j = nbr_[static_cast<std::size_t>(n)];
      if (j >= static_cast<int>(i)) continue;  // a ghost (j >= n_owned) or evaluated here
      // j's list is sorted by global id: find i's entry in it
      const std::int64_t id = owned_[i].id;
      const auto first = nbr_.begin() + nbr_start_[static_cast<std::size_t>(j)];
      const auto last = nbr_.begin() + nbr_start_[static_cast<std::size_t>(j) + 1];
      const auto it = std::lower_bound(first, last, id, [&](int q, std::int64_t v) {
        return at(static_cast<std::size_t>(q)).id < v;
      });
      if (it != last && *it == static_cast<int>(i))
        mirror_[static_cast<std::size_t>(n)] = static_cast<int>(it - nbr_.begin());
    }
  // Obstacles: a solid moves less than half the skin between rebuilds (maybe_rebuild), so an
  // obstacle whose box lies farther than radius + gap + skin cannot come within contact reach
  // before the next rebuild (obstacle_pair's own test is radius + gap).
  for (std::size_t i = 0; i < n_owned; ++i) {
    const SolidState& s = owned_[i];
    const double reach = shapes_[static_cast<std::size_t>(s.shape)].radius + extra;
    const core::Box2 around{{s.x.x - reach, s.x.z - reach}, {s.x.x + reach, s.x.z + reach}};
    for (std::size_t o = 0; o < obstacle_boxes_.size(); ++o)
      if (obstacle_boxes_[o].overlaps(around)) obs_.push_back(static_cast<int>(o));
    obs_start_[i + 1] = static_cast<int>(obs_.size());
  }
}

void DemSolver::rebuild() {
  exchange();
  borders();
  build_neighbours();
  x_at_build_.resize(owned_.size());
  for (std::size_t i = 0; i < owned_.size(); ++i) x_at_build_[i] = owned_[i].x;
  ++rebuilds_;
}

// Verlet criterion: rebuild once any solid has moved more than (almost) half the skin.
void DemSolver::maybe_rebuild() {
  double moved = 0.0;
  for (std::size_t i = 0; i < owned_.size(); ++i)
    moved = std::max(moved, core::norm2(owned_[i].x - x_at_build_[i]));
  if (comm_.size() > 1) moved = comm_.max(moved);
  if (std::sqrt(moved) > 0.45 * skin_) rebuild();
}

std::vector<SolidState> DemSolver::gather_all() const {
  std::vector<double> mine;
  for (const auto& s : owned_) pack_state(s, mine);
  const std::vector<double> all = comm_.size() > 1 ? comm_.all_gather(mine) : mine;
  std::vector<SolidState> out;
  for (std::size_t p = 0; p < all.size(); p += state_doubles) out.push_back(unpack_state(&all[p]));
  std::sort(out.begin(), out.end(),
            [](const SolidState& a, const SolidState& b) { return a.id < b.id; });
  return out;
}

DemSolver::Snapshot DemSolver::snapshot() const {
  Snapshot snap;
  for (const auto& s : gather_all()) {
    snap.id.push_back(s.id);
    snap.x.push_back(s.x.x);
    snap.z.push_back(s.x.z);
    snap.theta.push_back(s.theta);
    snap.u.push_back(s.v.x);
    snap.w.push_back(s.v.z);
    snap.omega.push_back(s.omega);
  }
  std::vector<double> mine;
  for (std::size_t i = 0; i < owned_.size(); ++i)
    for (const auto& [key, s] : springs_[i])
      mine.insert(mine.end(), {static_cast<double>(owned_[i].id), static_cast<double>(key), s});
  const std::vector<double> all = comm_.size() > 1 ? comm_.all_gather(mine) : mine;
  std::vector<std::tuple<std::int64_t, std::int64_t, double>> springs;
  for (std::size_t p = 0; p < all.size(); p += 3)
    springs.emplace_back(static_cast<std::int64_t>(all[p]), static_cast<std::int64_t>(all[p + 1]),
                         all[p + 2]);
  std::sort(springs.begin(), springs.end());
  for (const auto& [i, j, s] : springs) {
    snap.spring_solid.push_back(i);
    snap.spring_partner.push_back(j);
    snap.spring.push_back(s);
  }
  return snap;
}

void DemSolver::set_regions(std::vector<core::Box2> regions) {
  const Snapshot snap = snapshot();
  regions_ = std::move(regions);
  restore(snap);
}

void DemSolver::restore(const Snapshot& snap) {
  owned_.clear();
  springs_.clear();
  v_start_.clear();
  omega_start_.clear();
  for (std::size_t n = 0; n < snap.id.size(); ++n) {
    const Statics& st = statics_of(snap.id[n]);
    SolidState s;
    s.id = snap.id[n];
    s.shape = st.shape;
    s.mass = st.mass;
    s.inertia = st.inertia;
    s.x = {snap.x[n], snap.z[n]};
    s.theta = snap.theta[n];
    s.v = {snap.u[n], snap.w[n]};
    s.omega = snap.omega[n];
    if (owner_of(s.x) != comm_.rank()) continue;
    // springs are sorted by solid (as snapshot() writes them)
    Springs sp;
    auto e = static_cast<std::size_t>(
        std::lower_bound(snap.spring_solid.begin(), snap.spring_solid.end(), s.id) -
        snap.spring_solid.begin());
    for (; e < snap.spring_solid.size() && snap.spring_solid[e] == s.id; ++e)
      sp.emplace_back(snap.spring_partner[e], snap.spring[e]);
    owned_.push_back(s);
    springs_.push_back(std::move(sp));
    v_start_.push_back(s.v);
    omega_start_.push_back(s.omega);
  }
  sort_owned();
  rebuild();
}

}  // namespace picdem::dem

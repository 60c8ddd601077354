#include "picdem/particles/particle_set.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "picdem/core/error.hpp"
#include "picdem/core/rng.hpp"
#include "stencil.hpp"

namespace picdem::particles {

void declare_parameters(core::ParamSchema& schema) {
  schema.section("particles", "Fluid marker particles: seeding and reseeding.");
  schema
      .integer("particles/per_cell_1d", 2,
               "particles per cell along each axis at seeding (2: 2 x 2 per cell)")
      .at_least(1)
      .at_most(8);
  schema
      .real("particles/jitter", 0.5,
            "random offset of seeded particles, as a share of the sub-cell spacing")
      .at_least(0.0)
      .at_most(1.0);
  schema
      .integer("particles/min_per_cell", 2,
               "reseeding adds particles in interior fluid cells holding fewer (0: reseeding off, "
               "no particle added or removed)")
      .at_least(0)
      .at_most(64);
  schema
      .integer("particles/max_per_cell", 8,
               "reseeding removes the particles with the largest ids above this many per cell "
               "(not with min_per_cell 0)")
      .at_least(1)
      .at_most(256);
  schema.integer("particles/seed", 1, "seed of the counter-based random numbers").at_least(0);
  schema.section("transfer", "Particle <-> grid velocity transfer.");
  schema.string("transfer/scheme", "flip", {"flip", "apic"},
                "flip: FLIP/PIC blend of grid velocity change and value; apic: affine PIC");
  schema
      .real("transfer/flip_ratio", 0.95,
            "share of FLIP in the FLIP/PIC blend (1: pure FLIP, 0: PIC); flip scheme only")
      .at_least(0.0)
      .at_most(1.0);
  schema.section("advection", "Particle advection through the grid velocity.");
  schema.string("advection/scheme", "rk2", {"rk2", "rk3"},
                "rk2: explicit midpoint; rk3: Ralston's third-order Runge-Kutta");
  schema.check([](const core::Params& p, std::vector<std::string>& errors) {
    const long long lo = p.integer("particles/min_per_cell");
    const long long hi = p.integer("particles/max_per_cell");
    const long long n1 = p.integer("particles/per_cell_1d");
    if (lo > hi) {
      std::ostringstream s;
      s << "key 'particles/min_per_cell' = " << lo << " exceeds 'particles/max_per_cell' = " << hi
        << "; allowed: min_per_cell <= max_per_cell";
      errors.push_back(s.str());
    }
    if (n1 * n1 > hi) {
      std::ostringstream s;
      s << "key 'particles/per_cell_1d' = " << n1 << " seeds " << n1 * n1
        << " particles per cell, more than 'particles/max_per_cell' = " << hi
        << "; allowed: per_cell_1d^2 <= max_per_cell";
      errors.push_back(s.str());
    }
  });
}

ParticleConfig config_from(const core::Params& params) {
  ParticleConfig c;
  c.per_cell_1d = static_cast<int>(params.integer("particles/per_cell_1d"));
  c.jitter = params.real("particles/jitter");
  c.min_per_cell = static_cast<int>(params.integer("particles/min_per_cell"));
  c.max_per_cell = static_cast<int>(params.integer("particles/max_per_cell"));
  c.seed = static_cast<std::uint64_t>(params.integer("particles/seed"));
  c.transfer =
      params.string("transfer/scheme") == "apic" ? TransferScheme::Apic : TransferScheme::Flip;
  c.flip_ratio = params.real("transfer/flip_ratio");
  c.advection =
      params.string("advection/scheme") == "rk3" ? AdvectionScheme::Rk3 : AdvectionScheme::Rk2;
  return c;
}

int required_halo(const ParticleConfig& /*config*/) {
  // one face beyond the particle's cell for the 2 x 2 stencil + two cells of motion per step
  return 3;
}

void ParticleSet::clear() {
  resize(0);
}

void ParticleSet::reserve(std::size_t n) {
  for (auto* v : {&x, &z, &u, &w, &cxx, &cxz, &czx, &czz}) v->reserve(n);
  id.reserve(n);
}

void ParticleSet::resize(std::size_t n) {
  for (auto* v : {&x, &z, &u, &w, &cxx, &cxz, &czx, &czz}) v->resize(n, 0.0);
  id.resize(n, 0);
}

void ParticleSet::push_back_from(const ParticleSet& o, std::size_t n) {
  x.push_back(o.x[n]);
  z.push_back(o.z[n]);
  u.push_back(o.u[n]);
  w.push_back(o.w[n]);
  cxx.push_back(o.cxx[n]);
  cxz.push_back(o.cxz[n]);
  czx.push_back(o.czx[n]);
  czz.push_back(o.czz[n]);
  id.push_back(o.id[n]);
}

void ParticleSet::push_back(std::int64_t gid, core::Vec2 p, core::Vec2 v, const double (&c)[4]) {
  x.push_back(p.x);
  z.push_back(p.z);
  u.push_back(v.x);
  w.push_back(v.z);
  cxx.push_back(c[0]);
  cxz.push_back(c[1]);
  czx.push_back(c[2]);
  czz.push_back(c[3]);
  id.push_back(gid);
}

namespace {
template <class T>
void keep_in(std::vector<T>& v, const std::vector<char>& keep) {
  std::size_t m = 0;
  for (std::size_t n = 0; n < v.size(); ++n)
    if (keep[n]) v[m++] = v[n];
  v.resize(m);
}
template <class T>
void permute_in(std::vector<T>& v, const std::vector<std::size_t>& order, std::vector<T>& tmp) {
  tmp.resize(v.size());
  for (std::size_t n = 0; n < order.size(); ++n) tmp[n] = v[order[n]];
  v.swap(tmp);
}
}  // namespace

void ParticleSet::keep_if(const std::vector<char>& keep) {
  for (auto* v : {&x, &z, &u, &w, &cxx, &cxz, &czx, &czz}) keep_in(*v, keep);
  keep_in(id, keep);
}

long long ParticleSet::scale_velocities(const std::function<double(core::Vec2)>& factor) {
  long long scaled = 0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double C = factor({x[n], z[n]});
    if (C < 1.0) {
      u[n] *= C, w[n] *= C;
      cxx[n] *= C, cxz[n] *= C, czx[n] *= C, czz[n] *= C;
      ++scaled;
    }
  }
  return scaled;
}

void ParticleSet::permute(const std::vector<std::size_t>& order) {
  std::vector<double> tmp;
  for (auto* v : {&x, &z, &u, &w, &cxx, &cxz, &czx, &czz}) permute_in(*v, order, tmp);
  std::vector<std::int64_t> tmp_id;
  permute_in(id, order, tmp_id);
}

core::Vec2 velocity_sum(const ParticleSet& particles, const core::Comm& comm) {
  double sx = 0.0, sz = 0.0;
  for (std::size_t n = 0; n < particles.size(); ++n) sx += particles.u[n], sz += particles.w[n];
  return {comm.sum(sx), comm.sum(sz)};
}

namespace {

// A seeded particle of one dual cell (the square between four cell centres, around a grid node),
// in sub-cell units: its lattice position relative to the node and its jitter (u, v).
struct Member {
  int i, k;              // its cell
  std::uint64_t gid, n;  // its cell's global id and its index in the cell: its random numbers' keys
  double x, z;
  bool free_x, free_z;  // false on a cell's centre line (odd per_cell_1d): not jittered across it
  double u = 0.0, v = 0.0;
};

// Draws of one axis for every member, jitter (r - 1/2) on the free ones, less their mean;
// returns the largest |offset|.
double draw_axis(std::vector<Member>& m, const ParticleConfig& c, int axis, int attempt) {
  double sum = 0.0, largest = 0.0;
  int free = 0;
  for (Member& p : m) {
    const bool f = axis == 0 ? p.free_x : p.free_z;
    const double r =
        core::uniform01(c.seed, p.gid, p.n, static_cast<std::uint64_t>(2 * attempt + axis));
    (axis == 0 ? p.u : p.v) = f ? c.jitter * (r - 0.5) : 0.0;
    sum += f ? (axis == 0 ? p.u : p.v) : 0.0, free += f;
  }
  for (Member& p : m) {
    double& o = axis == 0 ? p.u : p.v;
    if (axis == 0 ? p.free_x : p.free_z) o -= sum / free;
    largest = std::max(largest, std::abs(o));
  }
  return largest;
}

// Moves v (least change, keeping its mean 0) onto sum (x + u) v = -sum z u: with the means 0
// that is sum (x + u)(z + v) = sum x z. Returns false when no v satisfies it.
bool keep_xz_sum(std::vector<Member>& m) {
  double mean = 0.0, d = 0.0, cc = 0.0, cv = 0.0;
  int free = 0;
  for (const Member& p : m) {
    d -= p.z * p.u;
    if (p.free_z) mean += p.x + p.u, ++free;
  }
  if (free > 0) mean /= free;
  for (const Member& p : m)
    if (p.free_z) cc += (p.x + p.u - mean) * (p.x + p.u - mean), cv += (p.x + p.u - mean) * p.v;
  if (cc < 1e-24) return std::abs(d) < 1e-12;
  const double lambda = (d - cv) / cc;
  for (Member& p : m)
    if (p.free_z) p.v += lambda * (p.x + p.u - mean);
  return true;
}

// The jitter of one dual cell's members (sub-cell units). They keep the lattice's sums of x, z
// and x z over the members, so the bilinear tent on the four cell centres around them (the
// occupancy) gets the lattice's weights exactly. u and v are drawn with mean 0 and v then moved
// onto the x z sum (keep_xz_sum); a draw with an offset outside (-jitter/2, jitter/2) is drawn
// again. After 8 draws, u = 0 (then the x z sum is linear in v) and v is scaled into the range.
void jitter_group(std::vector<Member>& m, const ParticleConfig& c) {
  const double bound = 0.5 * c.jitter;
  constexpr int attempts = 8;
  for (int attempt = 0; attempt < attempts; ++attempt) {
    if (draw_axis(m, c, 0, attempt) >= bound) continue;
    draw_axis(m, c, 1, attempt);
    if (!keep_xz_sum(m)) continue;
    double largest = 0.0;
    for (const Member& p : m) largest = std::max(largest, std::abs(p.v));
    if (largest < bound) return;
  }
  for (Member& p : m) p.u = 0.0;
  draw_axis(m, c, 1, attempts);
  keep_xz_sum(m);
  double largest = 0.0;
  for (const Member& p : m) largest = std::max(largest, std::abs(p.v));
  if (largest >= bound)
    for (Member& p : m) p.v *= 0.99 * bound / largest;
}

// The members of the dual cell around node (I, K): per cell, the sub-cell particles on the
// node's side of the cell's centre lines (the centre line itself goes with the node above it).
void members_of(int I, int K, int n1, const grid::GridSpec& s,
                const std::function<bool(int, int)>& seeded,
                const std::function<bool(core::Vec2)>& keep, std::vector<Member>& m) {
  const double sub = s.h / n1;
  m.clear();
  for (int k = K - 1; k <= K; ++k)
    for (int i = I - 1; i <= I; ++i) {
      if (i < 0 || k < 0 || i >= s.nx || k >= s.nz || !seeded(i, k)) continue;
      const auto gid = static_cast<std::uint64_t>(s.cell_gid(i, k));
      for (int b = 0; b < n1; ++b)
        for (int a = 0; a < n1; ++a) {
          if ((i == I) != (2 * a + 1 < n1) || (k == K) != (2 * b + 1 < n1)) continue;
          if (keep && !keep({s.origin.x + i * s.h + (a + 0.5) * sub,
                             s.origin.z + k * s.h + (b + 0.5) * sub}))
            continue;
          m.push_back({i, k, gid, static_cast<std::uint64_t>(b * n1 + a), (i - I) * n1 + a + 0.5,
                       (k - K) * n1 + b + 0.5, 2 * a + 1 != n1, 2 * b + 1 != n1});
        }
    }
}

}  // namespace

ParticleSet seed(const grid::Decomposition& d, const ParticleConfig& config,
                 const std::function<bool(core::Vec2)>& inside,
                 const std::function<bool(core::Vec2)>& keep) {
  const grid::GridSpec& s = d.spec();
  const core::IndexBox cells = d.owned_cells();
  const int n1 = config.per_cell_1d, nn = n1 * n1;
  const double sub = s.h / n1;  // sub-cell spacing
  // whether a cell is seeded, over the owned cells and one ring (the dual cells reach it)
  const core::IndexBox ring = cells.grown(1);
  std::vector<char> seeded_cell(static_cast<std::size_t>(ring.nx()) * ring.nz(), 0);
  for (int k = std::max(ring.k0, 0); k < std::min(ring.k1, s.nz); ++k)
    for (int i = std::max(ring.i0, 0); i < std::min(ring.i1, s.nx); ++i)
      seeded_cell[static_cast<std::size_t>(k - ring.k0) * ring.nx() + (i - ring.i0)] =
          inside(s.position(grid::Stagger::Cell, i, k));
  const auto seeded = [&](int i, int k) {
    return seeded_cell[static_cast<std::size_t>(k - ring.k0) * ring.nx() + (i - ring.i0)] != 0;
  };
  // the jitter of the owned cells' particles, dual cell by dual cell (the same on every rank)
  const auto slot = [&](int i, int k, int n) {
    return (static_cast<std::size_t>(k - cells.k0) * cells.nx() + (i - cells.i0)) * nn + n;
  };
  std::vector<double> ju(static_cast<std::size_t>(cells.nx()) * cells.nz() * nn, 0.0);
  std::vector<double> jv(ju.size(), 0.0);
  if (config.jitter > 0.0) {
    std::vector<Member> m;
    for (int K = cells.k0; K <= cells.k1; ++K)
      for (int I = cells.i0; I <= cells.i1; ++I) {
        members_of(I, K, n1, s, seeded, keep, m);
        if (m.empty()) continue;
        jitter_group(m, config);
        for (const Member& p : m) {
          if (!cells.contains(p.i, p.k)) continue;
          ju[slot(p.i, p.k, static_cast<int>(p.n))] = p.u;
          jv[slot(p.i, p.k, static_cast<int>(p.n))] = p.v;
        }
      }
  }
  ParticleSet p;
  p.spec = s;
  const double zero[4] = {0.0, 0.0, 0.0, 0.0};
  for (int k = cells.k0; k < cells.k1; ++k)
    for (int i = cells.i0; i < cells.i1; ++i) {
      if (!seeded(i, k)) continue;
      const auto gid = static_cast<std::uint64_t>(s.cell_gid(i, k));
      for (int b = 0; b < n1; ++b)
        for (int a = 0; a < n1; ++a) {
          const int n = b * n1 + a;
          // x = x_cell + (a + 1/2 + u) h / n1
          const core::Vec2 pos{s.origin.x + i * s.h + (a + 0.5 + ju[slot(i, k, n)]) * sub,
                               s.origin.z + k * s.h + (b + 0.5 + jv[slot(i, k, n)]) * sub};
          p.push_back(static_cast<std::int64_t>(gid * nn + static_cast<std::uint64_t>(n)), pos,
                      {0.0, 0.0}, zero);
        }
    }
  return p;
}

std::int64_t first_reseed_id(const grid::GridSpec& spec, const ParticleConfig& config) {
  return static_cast<std::int64_t>(spec.nx) * spec.nz * config.per_cell_1d * config.per_cell_1d;
}

void sort_by_cell(ParticleSet& p, const grid::GridSpec& spec) {
  const std::size_t n = p.size();
  if (n < 2) return;
  // the cell of GridSpec::cell_of (the same arithmetic), clamped to the grid
  std::vector<long long> key(n);
  for (std::size_t m = 0; m < n; ++m) {
    int i, k;
    detail::cell_of(spec, p.x[m], p.z[m], i, k);
    key[m] = spec.cell_gid(std::clamp(i, 0, spec.nx - 1), std::clamp(k, 0, spec.nz - 1));
  }
  const auto before = [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : p.id[a] < p.id[b];
  };
  bool sorted = true;
  for (std::size_t m = 1; m < n && sorted; ++m) sorted = before(m - 1, m);
  if (sorted) return;  // (cell, id) is unique: already the order of the set
  const auto [lo, hi] = std::minmax_element(key.begin(), key.end());
  const long long k0 = *lo, range = *hi - *lo + 1;
  std::vector<std::size_t> order(n);
  if (range > static_cast<long long>(8 * n + 1024)) {
    for (std::size_t m = 0; m < n; ++m) order[m] = m;
    std::sort(order.begin(), order.end(), before);
  } else {
    // counting sort by cell, then by id inside each cell (a handful of particles: insertion)
    std::vector<std::size_t> start(static_cast<std::size_t>(range) + 1, 0);
    for (std::size_t m = 0; m < n; ++m) ++start[static_cast<std::size_t>(key[m] - k0) + 1];
    for (std::size_t c = 0; c < static_cast<std::size_t>(range); ++c) start[c + 1] += start[c];
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t m = 0; m < n; ++m) order[fill[static_cast<std::size_t>(key[m] - k0)]++] = m;
    for (std::size_t c = 0; c < static_cast<std::size_t>(range); ++c)
      for (std::size_t a = start[c] + 1; a < start[c + 1]; ++a) {
        // (cell, id) is unique: the order does not depend on the order particles arrived in
        const std::size_t v = order[a];
        std::size_t b = a;
        for (; b > start[c] && p.id[order[b - 1]] > p.id[v]; --b) order[b] = order[b - 1];
        order[b] = v;
      }
  }
  p.permute(order);
}

}  // namespace picdem::particles

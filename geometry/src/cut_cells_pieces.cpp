// Wetted boundary pieces: a body's pieces (from cut_cells_clip.cpp) that no other body hides,
// with the integrals of n dl and (r x n) dl, their first moments about the cell centre, and their
// area terms 1/2 integral (x dz - z dx); consecutive pieces in one cell are chained into one.
#include <algorithm>
#include <cmath>

#include "cut_cells_internal.hpp"

namespace picdem::geometry::detail {

// The first moments of WettedPiece about the centre of cell (i, k), in world units, for a
// segment (p0 -> p1) or an arc (centre c, radius rho, from phi0 over dphi), all in window units
// (world = origin + h u); com is the body's centre of mass (window units), null for obstacles.
void set_moments(WettedPiece& p, const Sub& s, int i, int k, double h, const Vec2* com) {
  const Vec2 uc{i + 0.5, k + 0.5};
  const Vec2 d = s.p1 - s.p0, n_dl{d.z, -d.x};  // window units
  Vec2 mx, mz;                                  // int (u - uc)_x n dl_w, int (u - uc)_z n dl_w
  if (s.arc) {
    // u - uc = (c - uc) + rho n(phi), dl = rho dphi: int n n^T dphi in closed form
    const double a = s.phi0, b = s.phi0 + s.dphi;
    const double cc = 0.5 * s.dphi + 0.25 * (std::sin(2 * b) - std::sin(2 * a));
    const double ss = 0.5 * s.dphi - 0.25 * (std::sin(2 * b) - std::sin(2 * a));
    const double cs = 0.5 * (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a));
    const double r2 = s.rho * s.rho;
    const Vec2 e = s.c - uc;
    mx = Vec2{e.x * n_dl.x + r2 * cc, e.x * n_dl.z + r2 * cs};
    mz = Vec2{e.z * n_dl.x + r2 * cs, e.z * n_dl.z + r2 * ss};
  } else {
    const Vec2 m = 0.5 * (s.p0 + s.p1) - uc;  // n is constant: the midpoint rule is exact
    mx = m.x * n_dl;
    mz = m.z * n_dl;
  }
  p.dx_n_dl = h * h * mx;
  p.dz_n_dl = h * h * mz;
  p.d_r_cross_n_dl = Vec2{};
  if (!com) return;
  if (s.arc) {
    // r x n = (c - com) x n on an arc about c: linear in n
    const Vec2 l = s.c - *com;
    p.d_r_cross_n_dl = h * h * h * Vec2{l.x * mx.z - l.z * mx.x, l.x * mz.z - l.z * mz.x};
  } else {
    // (u - uc) and (u - com) x n_dl are linear along the segment: Simpson is exact
    auto t = [&](const Vec2& u) { return (u.x - com->x) * n_dl.z - (u.z - com->z) * n_dl.x; };
    const Vec2 a = s.p0 - uc, b = s.p1 - uc, m = 0.5 * (a + b);
    const Vec2 mid = 0.5 * (s.p0 + s.p1);
    const Vec2 sum = t(s.p0) * a + 4.0 * t(mid) * m + t(s.p1) * b;
    p.d_r_cross_n_dl = (h * h * h / 6.0) * sum;
  }
}

namespace {

// 1/2 (x dz - z dx) integrated over the piece, relative to the centre of its cell.
double area_term(const Sub& s) {
  const Vec2 c{s.i + 0.5, s.k + 0.5};
  double a = 0.5 * core::cross(s.p0 - c, s.p1 - c);
  if (s.arc) {
    // circular segment between chord and arc: rho^2 / 2 (dphi - sin dphi)
    const double x = s.dphi;
    const double f =
        x < 1e-2 ? x * x * x / 6.0 * (1.0 - x * x / 20.0 * (1.0 - x * x / 42.0)) : x - std::sin(x);
    a += 0.5 * s.rho * s.rho * f;
  }
  return a;
}

/// True when the piece's midpoint (on the arc for arcs) lies inside or on another body.
bool hidden_by_neighbour(const Sub& s, const std::vector<Item>& items,
                         const std::vector<int>& neighbours, const GridWindow& w) {
  if (neighbours.empty()) return false;
  Vec2 m = 0.5 * (s.p0 + s.p1);
  if (s.arc) {
    const double am = s.phi0 + 0.5 * s.dphi;
    m = s.c + s.rho * Vec2{std::cos(am), std::sin(am)};
  }
  for (int o : neighbours) {
    const Item& other = items[o];
    if (m.x < other.lo_x || m.x > other.hi_x || m.z < other.lo_z || m.z > other.hi_z) continue;
    if (other.contains_world(w.origin + w.h * m)) return true;
  }
  return false;
}

/// The wetted piece of the item's boundary piece s, in world units.
WettedPiece make_piece(const Item& it, const Sub& s, const GridWindow& w) {
  auto world = [&w](const Vec2& u) { return w.origin + w.h * u; };
  const Vec2 d = s.p1 - s.p0;
  WettedPiece p;
  p.body = it.tag;
  p.i = s.i;
  p.k = s.k;
  p.p0 = world(s.p0);
  p.p1 = world(s.p1);
  // integral of n dl = (d zeta, -d xi) h for any curve with the body on its left
  p.n_dl = w.h * Vec2{d.z, -d.x};
  if (it.tag >= 0) {
    // (r x n) dl = -d(|r|^2 / 2): -(p1 - p0) . ((p0 + p1) / 2 - X); on an arc about c,
    // -(p1 - p0) . (c - X)
    const Vec2 lever = s.arc ? s.c - it.com : 0.5 * (s.p0 + s.p1) - it.com;
    p.r_cross_n_dl = -w.h * w.h * core::dot(d, lever);
  }
  set_moments(p, s, s.i, s.k, w.h, it.tag >= 0 ? &it.com : nullptr);
  p.length = w.h * (s.arc ? s.rho * s.dphi : core::norm(d));
  return p;
}

/// Adds the integrals of b to a (a's run now ends where b's ends: the caller sets the joint).
void absorb(WettedPiece& a, const WettedPiece& b) {
  a.n_dl += b.n_dl;
  a.r_cross_n_dl += b.r_cross_n_dl;
  a.dx_n_dl += b.dx_n_dl;
  a.dz_n_dl += b.dz_n_dl;
  a.d_r_cross_n_dl += b.d_r_cross_n_dl;
  a.length += b.length;
}

}  // namespace

void item_pieces(const Item& it, const std::vector<Item>& items, const std::vector<int>& neighbours,
                 Builder& bd) {
  const int bnx = bd.B.nx(), bnz = bd.B.nz();
  bd.term.assign(static_cast<std::size_t>(bnx) * bnz, 0.0);
  bd.touched.assign(static_cast<std::size_t>(bnx) * bnz, 0);
  std::vector<WettedPiece> chain;
  for (const Sub& s : bd.subs) {
    if (!bd.B.contains(s.i, s.k)) continue;
    if (hidden_by_neighbour(s, items, neighbours, bd.win)) continue;
    const std::size_t c = (s.i - bd.B.i0) + static_cast<std::size_t>(s.k - bd.B.k0) * bnx;
    const double a_piece = area_term(s);
    bd.term[c] += a_piece;
    bd.covered[bd.cell(s.i, s.k)] += a_piece;
    bd.touched[c] = 1;
    const WettedPiece p = make_piece(it, s, bd.win);
    if (!chain.empty() && chain.back().i == p.i && chain.back().k == p.k &&
        chain.back().p1 == p.p0) {
      chain.back().p1 = p.p1;
      absorb(chain.back(), p);
    } else {
      chain.push_back(p);
    }
  }
  // The loop is closed: its last run joins the first when they share a cell.
  if (chain.size() > 1 && chain.back().i == chain.front().i && chain.back().k == chain.front().k &&
      chain.back().p1 == chain.front().p0) {
    chain.front().p0 = chain.back().p0;
    absorb(chain.front(), chain.back());
    chain.pop_back();
  }
  bd.pieces.insert(bd.pieces.end(), chain.begin(), chain.end());
}

}  // namespace picdem::geometry::detail

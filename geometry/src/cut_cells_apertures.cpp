// Apertures: the covered intervals of every grid line (winding number of a body's crossings of the
// line shifted by +eps and -eps, united over bodies), the open length E_f of every face (eq. 5),
// the covered area per cell of each body (for the cutting body) and the fluid fraction of the
// union: covered area = 1/4 (sum of the covered lengths of the cell's faces) + the area terms of
// the visible boundary pieces (cut_cells_pieces.cpp).
#include <algorithm>

#include "cut_cells_internal.hpp"

namespace picdem::geometry::detail {

void merge(std::vector<Interval>& v) {
  if (v.size() < 2) return;
  std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  std::size_t n = 0;
  for (std::size_t j = 1; j < v.size(); ++j) {
    if (v[j].lo <= v[n].hi) {
      v[n].hi = std::max(v[n].hi, v[j].hi);
    } else {
      v[++n] = v[j];
    }
  }
  v.resize(n + 1);
}

void sweep(std::vector<std::pair<double, int>>& ev, std::vector<Interval>& out) {
  std::sort(ev.begin(), ev.end());
  int w = 0;
  double start = 0.0;
  for (const auto& [z, d] : ev) {
    const int before = w;
    w += d;
    if (before <= 0 && w > 0) start = z;
    if (before > 0 && w <= 0 && z > start) out.push_back({start, z});
  }
}

void distribute(const std::vector<Interval>& v, int c0, int c1, double* c) {
  for (const auto& iv : v) {
    const int a = std::max(c0, floor_int(iv.lo)), b = std::min(c1 - 1, floor_int(iv.hi));
    for (int k = a; k <= b; ++k) {
      const double len = std::min(iv.hi, k + 1.0) - std::max(iv.lo, static_cast<double>(k));
      if (len > 0) c[k - c0] += len;
    }
  }
}

void finish_coverage(Builder& bd) {
  for (int j = bd.B.i0; j <= bd.B.i1; ++j) {
    auto& v = bd.lx[j - bd.B.i0];
    sweep(bd.ex_plus[j - bd.B.i0], v);
    sweep(bd.ex_minus[j - bd.B.i0], v);
    merge(v);
  }
  for (int k = bd.B.k0; k <= bd.B.k1; ++k) {
    auto& v = bd.lz[k - bd.B.k0];
    sweep(bd.ez_plus[k - bd.B.k0], v);
    sweep(bd.ez_minus[k - bd.B.k0], v);
    merge(v);
  }
}

void item_face_coverage(Builder& bd) {
  const int bnx = bd.B.nx(), bnz = bd.B.nz();
  bd.cx.assign(static_cast<std::size_t>(bnx + 1) * bnz, 0.0);
  bd.cz.assign(static_cast<std::size_t>(bnx) * (bnz + 1), 0.0);
  for (int j = 0; j <= bnx; ++j) {
    merge(bd.lx[j]);
    std::vector<double> col(bnz, 0.0);
    distribute(bd.lx[j], bd.B.k0, bd.B.k1, col.data());
    for (int k = 0; k < bnz; ++k) bd.cx[j + static_cast<std::size_t>(k) * (bnx + 1)] = col[k];
    auto& g = bd.gx[bd.B.i0 + j - bd.W.i0];
    g.insert(g.end(), bd.lx[j].begin(), bd.lx[j].end());
  }
  for (int k = 0; k <= bnz; ++k) {
    merge(bd.lz[k]);
    distribute(bd.lz[k], bd.B.i0, bd.B.i1, &bd.cz[static_cast<std::size_t>(k) * bnx]);
    auto& g = bd.gz[bd.B.k0 + k - bd.W.k0];
    g.insert(g.end(), bd.lz[k].begin(), bd.lz[k].end());
  }
}

void item_cell_areas(const Item& it, Builder& bd) {
  // Covered area per cell: (1/4) sum of covered face lengths + sum of 1/2 (x dz - z dx).
  const int bnx = bd.B.nx(), bnz = bd.B.nz();
  for (int k = 0; k < bnz; ++k) {
    for (int i = 0; i < bnx; ++i) {
      const std::size_t c = i + static_cast<std::size_t>(k) * bnx;
      const double faces = bd.cx[i + static_cast<std::size_t>(k) * (bnx + 1)] +
                           bd.cx[i + 1 + static_cast<std::size_t>(k) * (bnx + 1)] +
                           bd.cz[i + static_cast<std::size_t>(k) * bnx] +
                           bd.cz[i + static_cast<std::size_t>(k + 1) * bnx];
      if (faces == 0.0 && !bd.touched[c]) continue;
      const double area = std::clamp(0.25 * faces + bd.term[c], 0.0, 1.0);
      const long long g = bd.cell(bd.B.i0 + i, bd.B.k0 + k);
      if (it.tag >= 0) {
        if (area > bd.best_solid_area[g]) {
          bd.best_solid_area[g] = area;
          bd.best_solid[g] = it.tag;
        }
      } else if (area > bd.best_obstacle_area[g]) {
        bd.best_obstacle_area[g] = area;
        bd.best_obstacle[g] = -1 - it.tag;
      }
    }
  }
}

namespace {

/// Subtracts the covered length of each face on the lines `lines` (units of h) from the open
/// lengths E[base + line * line_step + cell * cell_step], cells c0 .. c1 - 1 along each line.
void subtract_covered(std::vector<std::vector<Interval>>& lines, int c0, int c1,
                      std::size_t line_step, std::size_t cell_step, std::vector<double>& E) {
  std::vector<double> covered(c1 - c0);
  for (std::size_t j = 0; j < lines.size(); ++j) {
    auto& v = lines[j];
    if (v.empty()) continue;
    merge(v);
    std::fill(covered.begin(), covered.end(), 0.0);
    distribute(v, c0, c1, covered.data());
    for (int k = 0; k < c1 - c0; ++k) E[j * line_step + k * cell_step] -= covered[k];
  }
}

/// E_f = h - (covered length of face f), the union over all bodies (the E of eq. 5), in units of h.
void union_open_lengths(Builder& bd, CutCells& cc) {
  cc.ex.assign(static_cast<std::size_t>(bd.nwx + 1) * bd.nwz, 1.0);
  cc.ez.assign(static_cast<std::size_t>(bd.nwx) * (bd.nwz + 1), 1.0);
  subtract_covered(bd.gx, bd.W.k0, bd.W.k1, 1, bd.nwx + 1, cc.ex);
  subtract_covered(bd.gz, bd.W.i0, bd.W.i1, bd.nwx, 1, cc.ez);
  for (auto& e : cc.ex) e = std::max(0.0, e);
  for (auto& e : cc.ez) e = std::max(0.0, e);
}

}  // namespace

void union_apertures(Builder& bd, CutCells& cc) {
  union_open_lengths(bd, cc);
  // Covered area of the union: 1/4 (sum of covered face lengths) + the visible pieces' terms.
  cc.fraction = std::move(bd.covered);
  for (int k = 0; k < bd.nwz; ++k) {
    for (int i = 0; i < bd.nwx; ++i) {
      const std::size_t c = i + static_cast<std::size_t>(k) * bd.nwx;
      const std::size_t fx = i + static_cast<std::size_t>(k) * (bd.nwx + 1);
      const double open = cc.ex[fx] + cc.ex[fx + 1] + cc.ez[c] + cc.ez[c + bd.nwx];
      if (open == 4.0 && cc.fraction[c] == 0.0) {
        cc.fraction[c] = 1.0;
        continue;
      }
      const double covered = 0.25 * (4.0 - open) + cc.fraction[c];
      cc.fraction[c] = 1.0 - std::clamp(covered, 0.0, 1.0);
    }
  }
}

}  // namespace picdem::geometry::detail

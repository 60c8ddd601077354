#include "picdem/grid/balance.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "picdem/core/error.hpp"

namespace picdem::grid {

std::vector<int> split_weighted(const std::vector<long long>& w, int parts, int min_width) {
  const int n = static_cast<int>(w.size());
  std::vector<long long> sum(w.size() + 1, 0);
  for (std::size_t i = 0; i < w.size(); ++i) sum[i + 1] = sum[i] + w[i];
  const long long total = sum.back();
  std::vector<int> starts(static_cast<std::size_t>(parts) + 1, 0);
  starts.back() = n;
  for (int j = 1; j < parts; ++j) {
    // share j of parts: the first c with sum[c] * parts >= total * j, or the one before it
    const long long goal = total * j;
    int c =
        static_cast<int>(std::lower_bound(sum.begin(), sum.end(), goal,
                                          [&](long long s, long long g) { return s * parts < g; }) -
                         sum.begin());
    if (c > 0 && goal - sum[static_cast<std::size_t>(c) - 1] * parts <
                     sum[static_cast<std::size_t>(c)] * parts - goal)
      --c;
    const int lo = starts[static_cast<std::size_t>(j) - 1] + min_width;
    const int hi = n - (parts - j) * min_width;
    starts[static_cast<std::size_t>(j)] = std::min(std::max(c, lo), hi);
  }
  return starts;
}

namespace {

// Column and row sums of the work over the whole grid (collective).
void line_sums(const Decomposition& d, const std::vector<long long>& work,
               std::vector<long long>& col, std::vector<long long>& row) {
  const auto& spec = d.spec();
  const IndexBox own = d.owned_cells();
  std::vector<long long> both(static_cast<std::size_t>(spec.nx + spec.nz), 0);
  std::size_t n = 0;
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i, ++n) {
      both[static_cast<std::size_t>(i)] += work[n];
      both[static_cast<std::size_t>(spec.nx + k)] += work[n];
    }
  d.comm().sum_in_place(both);
  col.assign(both.begin(), both.begin() + spec.nx);
  row.assign(both.begin() + spec.nx, both.end());
}

// Adds this rank's work into the blocks of `c` (px * pz entries, rank order) at `out`.
void add_block_work(const Decomposition& d, const std::vector<long long>& work, const Cuts& c,
                    long long* out) {
  const IndexBox own = d.owned_cells();
  const int px = static_cast<int>(c.xs.size()) - 1;
  std::vector<int> strip(static_cast<std::size_t>(own.nx()));
  for (int i = own.i0; i < own.i1; ++i)
    strip[static_cast<std::size_t>(i - own.i0)] =
        static_cast<int>(std::upper_bound(c.xs.begin() + 1, c.xs.end() - 1, i) - c.xs.begin()) - 1;
  std::size_t n = 0;
  for (int k = own.k0; k < own.k1; ++k) {
    const int cz =
        static_cast<int>(std::upper_bound(c.zs.begin() + 1, c.zs.end() - 1, k) - c.zs.begin()) - 1;
    for (int i = own.i0; i < own.i1; ++i, ++n)
      out[cz * px + strip[static_cast<std::size_t>(i - own.i0)]] += work[n];
  }
}

}  // namespace

Cuts balanced_cuts(const Decomposition& d, const std::vector<long long>& work, int ranks_x,
                   int ranks_z) {
  const auto& spec = d.spec();
  const int p = d.comm().size(), m = d.halo() + 1;
  std::vector<long long> col, row;
  line_sums(d, work, col, row);
  std::vector<Cuts> candidates;
  for (int a = 1; a <= p; ++a) {
    const int b = p / a;
    if (p % a || (ranks_x > 0 && a != ranks_x) || (ranks_z > 0 && b != ranks_z)) continue;
    if (spec.nx < a * m || spec.nz < b * m) continue;
    candidates.push_back({split_weighted(col, a, m), split_weighted(row, b, m), 0});
  }
  if (candidates.empty()) {
    std::ostringstream s;
    s << "cannot split the " << spec.nx << " x " << spec.nz << " grid over " << p
      << " ranks (grid/ranks_x = " << ranks_x << ", grid/ranks_z = " << ranks_z
      << ") in strips of at least " << m << " cells";
    throw core::InputError(s.str());
  }
  std::vector<std::size_t> offset(candidates.size() + 1, 0);
  for (std::size_t c = 0; c < candidates.size(); ++c) offset[c + 1] = offset[c] + p;
  std::vector<long long> blocks(offset.back(), 0);
  for (std::size_t c = 0; c < candidates.size(); ++c)
    add_block_work(d, work, candidates[c], blocks.data() + offset[c]);
  d.comm().sum_in_place(blocks);
  // The lightest heaviest block; among the process grids within 10% of it, the one with the most
  // column strips: water settles at the bottom under gravity and spreads along x, so row cuts
  // soon leave the upper strips empty while column cuts keep following it.
  long long lightest = -1;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    candidates[c].heaviest = *std::max_element(blocks.begin() + static_cast<long>(offset[c]),
                                               blocks.begin() + static_cast<long>(offset[c + 1]));
    if (lightest < 0 || candidates[c].heaviest < lightest) lightest = candidates[c].heaviest;
  }
  Cuts* best = nullptr;
  for (Cuts& k : candidates)
    if (k.heaviest * 10 <= lightest * 11 && (!best || k.xs.size() > best->xs.size())) best = &k;
  for (long long c : col) best->total += c;
  return *best;
}

long long heaviest_block(const Decomposition& d, const std::vector<long long>& work) {
  std::vector<long long> blocks(static_cast<std::size_t>(d.size()), 0);
  add_block_work(d, work, {d.x_cuts(), d.z_cuts(), 0}, blocks.data());
  d.comm().sum_in_place(blocks);
  return *std::max_element(blocks.begin(), blocks.end());
}

Cuts cuts_of_boxes(const GridSpec& spec, const std::vector<IndexBox>& owned_cells) {
  Cuts c;
  std::vector<int> xs{0}, zs{0};
  for (const auto& b : owned_cells)
    if (b.k0 == 0 && b.i1 != xs.back()) xs.push_back(b.i1);
  for (const auto& b : owned_cells)
    if (b.i0 == 0 && b.k1 != zs.back()) zs.push_back(b.k1);
  const std::size_t px = xs.size() - 1, pz = zs.size() - 1;
  if (xs.back() != spec.nx || zs.back() != spec.nz || px * pz != owned_cells.size()) return c;
  for (std::size_t r = 0; r < owned_cells.size(); ++r) {
    const std::size_t cx = r % px, cz = r / px;
    if (!(owned_cells[r] == IndexBox{xs[cx], xs[cx + 1], zs[cz], zs[cz + 1]})) return c;
  }
  c.xs = std::move(xs), c.zs = std::move(zs);
  return c;
}

BalanceRule balance_rule_from(const core::Params& params) {
  BalanceRule r;
  r.weighted = params.string("grid/decomposition") == "weighted";
  r.ranks_x = static_cast<int>(params.integer("grid/ranks_x"));
  r.ranks_z = static_cast<int>(params.integer("grid/ranks_z"));
  r.gain = params.real("grid/rebalance_gain");
  r.interval = params.integer("grid/rebalance_interval");
  return r;
}

std::optional<Cuts> worthwhile_cuts(const Decomposition& d, const std::vector<long long>& work,
                                    const BalanceRule& rule) {
  Cuts cuts = balanced_cuts(d, work, rule.ranks_x, rule.ranks_z);
  if (cuts.xs == d.x_cuts() && cuts.zs == d.z_cuts()) return std::nullopt;
  cuts.before = heaviest_block(d, work);
  if (static_cast<double>(cuts.heaviest) > (1.0 - rule.gain) * static_cast<double>(cuts.before))
    return std::nullopt;
  return cuts;
}

std::string describe(const Cuts& cuts) {
  auto list = [](const std::vector<int>& v) {
    std::string out;
    for (int c : v) out += (out.empty() ? "" : " ") + std::to_string(c);
    return out;
  };
  return "cut lines x {" + list(cuts.xs) + "}, z {" + list(cuts.zs) + "}, heaviest block " +
         std::to_string(cuts.before) + " -> " + std::to_string(cuts.heaviest) + " of " +
         std::to_string(cuts.total);
}

Cuts fitting_cuts_of_boxes(const GridSpec& spec, const std::vector<IndexBox>& owned_cells,
                           int ranks, const BalanceRule& rule) {
  Cuts cuts = cuts_of_boxes(spec, owned_cells);
  const auto strips = [](const std::vector<int>& c) { return static_cast<int>(c.size()) - 1; };
  const bool fit = owned_cells.size() == static_cast<std::size_t>(ranks) && !cuts.xs.empty() &&
                   (rule.ranks_x == 0 || rule.ranks_x == strips(cuts.xs)) &&
                   (rule.ranks_z == 0 || rule.ranks_z == strips(cuts.zs));
  return fit ? cuts : Cuts{};
}

}  // namespace picdem::grid

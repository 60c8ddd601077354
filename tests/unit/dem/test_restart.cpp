// Checkpoint: a run restored from a snapshot continues bitwise identically to the continuous run,
// including the accumulated tangential springs (the only contact history).
#include <gtest/gtest.h>

#include <cstring>

#include "dem_fixtures.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
std::vector<SolidSpec> pile() {
  std::vector<SolidSpec> s;
  const double r = 0.005, pitch = 0.011;
  std::int64_t id = 0;
  for (int layer = 0; layer < 4; ++layer)
    for (int c = 0; c < 4 - layer % 2; ++c)
      s.push_back(disk(
          id++, r, 2700.0,
          {0.006 + (layer % 2) * 0.0055 + c * pitch, 0.006 + layer * pitch * 0.8660254037844386}));
  return s;
}

bool same_bits(const std::vector<core::SolidState>& a, const std::vector<core::SolidState>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t n = 0; n < a.size(); ++n) {
    const double va[6] = {a[n].x.x, a[n].x.z, a[n].theta, a[n].v.x, a[n].v.z, a[n].omega};
    const double vb[6] = {b[n].x.x, b[n].x.z, b[n].theta, b[n].v.x, b[n].v.z, b[n].omega};
    if (a[n].id != b[n].id || std::memcmp(va, vb, sizeof va) != 0) return false;
  }
  return true;
}
}  // namespace

TEST(DemRestart, RestoredRunMatchesContinuousRunBitwise) {
  DemConfig cfg;
  cfg.h = 5e-4;
  cfg.tangential = TangentialModel::Accumulated;
  DemSolver a = solver(cfg, 0.1, 0.1);
  a.add_solids(pile());
  const double dt = 3e-4;
  for (int n = 0; n < 200; ++n) a.advance(dt, {});
  const auto snap = a.snapshot();
  EXPECT_FALSE(snap.spring.empty()) << "no tangential history to test";
  for (int n = 0; n < 200; ++n) a.advance(dt, {});

  DemSolver b = solver(cfg, 0.1, 0.1);
  b.add_solids(pile());
  b.restore(snap);
  const auto snap_b = b.snapshot();
  EXPECT_EQ(snap_b.spring, snap.spring);
  EXPECT_EQ(snap_b.spring_partner, snap.spring_partner);
  for (int n = 0; n < 200; ++n) b.advance(dt, {});
  EXPECT_TRUE(same_bits(a.gather_all(), b.gather_all()));
  // the pile has really moved since the snapshot
  EXPECT_GT(std::abs(a.gather_all()[12].x.z - snap.z[12]), 0.0);
}

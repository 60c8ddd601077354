// Validation: the dry collapse of 6 cylinder layers (cases/dry_collapse_6layers) against the
// experiment of Zhang et al. (2009): the mean centre (eq. 26) divided by the tank length within
// |d(x/L)| <= 0.03 and |d(z/L)| <= 0.015 at t = 0.1, 0.3 and 0.5 s. Writes the simulated curve and
// the comparison as CSV (doc/dem_dry_collapse_plot.py turns them into the PNG).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "dry_collapse_run.hpp"

using namespace picdem;
using namespace picdem::dem;
using namespace picdem::dem::testing;

namespace {
struct Row {
  double t, x, z;
};

std::vector<Row> experiment() {
  std::ifstream f(std::string(PICDEM_DATA_DIR) + "/zhang2009_dry_collapse_6layers.csv");
  std::vector<Row> rows;
  std::string line;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    Row r{};
    char c1, c2;
    std::istringstream(line) >> r.t >> c1 >> r.x >> c2 >> r.z;
    rows.push_back(r);
  }
  return rows;
}

Row interpolate(const std::vector<Row>& sim, double t) {
  for (std::size_t n = 1; n < sim.size(); ++n)
    if (sim[n].t >= t) {
      const double w = (t - sim[n - 1].t) / (sim[n].t - sim[n - 1].t);
      return {t, sim[n - 1].x + w * (sim[n].x - sim[n - 1].x),
              sim[n - 1].z + w * (sim[n].z - sim[n - 1].z)};
    }
  return sim.back();
}
}  // namespace

class DryCollapse : public ::testing::TestWithParam<std::string> {};

TEST_P(DryCollapse, MeanCentreFollowsTheExperiment) {
  const core::Comm comm;
  const std::string model = GetParam();
  const CollapseCase c = load_collapse(comm, {"dem/tangential_model=" + model});
  ASSERT_EQ(c.solids.size(), 33u);
  const double L = c.tank.hi.x - c.tank.lo.x;
  std::vector<Row> sim;
  std::string solids_csv = "t,id,x,z,theta,u,w,omega\n";
  const auto start = std::chrono::steady_clock::now();
  int subcycles = 0;
  run_collapse(comm, c, strips(c.tank, {}), [&](double t, const DemSolver& s) {
    const auto all = s.gather_all();
    // eq. 26: x_ave = sum X_i / N
    core::Vec2 mean{};
    for (const auto& b : all) mean += b.x;
    mean = mean / static_cast<double>(all.size());
    sim.push_back({t, mean.x / L, mean.z / L});
    append_solids_csv(solids_csv, t, all);
    subcycles = s.last_subcycles();
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "dry collapse (%s): resolution h = %g m (gap %g m), %zu outputs, %d subcycles per step of %g "
      "s, %.2f s wall clock\n",
      model.c_str(), c.cfg.h, c.cfg.gap(), sim.size(), subcycles, c.dt, seconds);

  std::ofstream curve("dem_dry_collapse_" + model + ".csv");
  curve << "t_s,xc_over_L,zc_over_L\n";
  for (const auto& r : sim) curve << r.t << ',' << r.x << ',' << r.z << '\n';
  std::ofstream("solids_" + model + ".csv") << solids_csv;

  const auto exp = experiment();
  ASSERT_EQ(exp.size(), 4u);
  EXPECT_NEAR(sim.front().x, exp.front().x, 0.002);  // the scaled tank reproduces the start
  std::ofstream cmp("dem_dry_collapse_comparison_" + model + ".csv");
  cmp << "t_s,xc_over_L_experiment,xc_over_L_simulation,dx,zc_over_L_experiment,"
         "zc_over_L_simulation,dz\n";
  for (const auto& e : exp) {
    const Row s = interpolate(sim, e.t);
    cmp << e.t << ',' << e.x << ',' << s.x << ',' << s.x - e.x << ',' << e.z << ',' << s.z << ','
        << s.z - e.z << '\n';
    std::printf("t = %.3f s: x/L exp %.4f sim %.4f (d %+.4f), z/L exp %.4f sim %.4f (d %+.4f)\n",
                e.t, e.x, s.x, s.x - e.x, e.z, s.z, s.z - e.z);
    if (e.t < 0.05) continue;
    EXPECT_NEAR(s.x, e.x, 0.03) << "t = " << e.t;
    EXPECT_NEAR(s.z, e.z, 0.015) << "t = " << e.t;
  }
}

// one_step: the paper's eq. 8 (the case file's choice); accumulated: Zhang et al. (2009)
INSTANTIATE_TEST_SUITE_P(TangentialModels, DryCollapse,
                         ::testing::Values(std::string("one_step"), std::string("accumulated")));

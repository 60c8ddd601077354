// forces.csv (doc/output.md) read back from a real run's output folder: the neutral disk's
// pressure force is its buoyancy rho g A (J p, eq. 6) and the immersed block of
// cases/still_tank_obstacle gets rho g A upwards with the torque rho g A x_centroid about (0, 0);
// viscous columns 0 with the explicit scheme; rows every step, or at output/forces_interval.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_loader.hpp"
#include "picdem/coupling/simulation.hpp"
#include "picdem/run/run.hpp"

using namespace picdem;

namespace {

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return static_cast<int>(c);
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

Csv read_csv(const std::string& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  for (std::stringstream s(line); std::getline(s, cell, ',');) csv.header.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::stringstream s(line); std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

// Runs `steps` steps of a case with output to a fresh folder; returns forces.csv (on every rank).
Csv run_and_read(const core::Comm& comm, const std::string& name, const std::string& case_path,
                 std::vector<std::string> settings, long long steps) {
  const std::string dir = "/tmp/picdem_test_forces_" + name + "_np" + std::to_string(comm.size());
  if (comm.is_root()) std::filesystem::remove_all(dir);
  comm.barrier();
  settings.insert(settings.end(), {"output/paraview=false", "output/png=false"});
  const auto params = test_support::load_case(comm, case_path, settings);
  {
    coupling::Simulation sim(comm, params);
    run::Run run(sim);
    run.open_output(dir);
    run.run(steps);
  }
  comm.barrier();
  return read_csv(dir + "/forces.csv");
}

}  // namespace

TEST(ForcesCsv, NeutralDiskPressureForceIsBuoyancy) {
  core::Comm comm;
  const Csv csv = run_and_read(comm, "neutral_disk", "cases/neutral_disk/case.yaml", {}, 3);
  const std::vector<std::string> expected{
      "t",         "id",        "obstacle",        "pressure_x",    "pressure_z",
      "viscous_x", "viscous_z", "torque_pressure", "torque_viscous"};
  EXPECT_EQ(csv.header, expected);
  ASSERT_EQ(csv.rows.size(), 3u);  // one solid, every step
  const double rho = 1000.0, g = 9.81, r = 0.01, buoyancy = rho * g * M_PI * r * r;
  const auto& last = csv.rows.back();
  if (comm.is_root())
    std::printf(
        "neutral disk, forces.csv at t = %.4f s: pressure (%.6f, %.6f) N/m, rho g A = "
        "%.6f, torque %.3e N m/m\n",
        last[0], last[3], last[4], buoyancy, last[7]);
  EXPECT_EQ(last[csv.column("id")], 0.0);
  EXPECT_EQ(last[csv.column("obstacle")], 0.0);
  EXPECT_NEAR(last[csv.column("pressure_z")], buoyancy, 1e-5 * buoyancy);
  EXPECT_NEAR(last[csv.column("pressure_x")], 0.0, 1e-5 * buoyancy);
  for (const char* c : {"viscous_x", "viscous_z", "torque_viscous"})
    EXPECT_EQ(last[csv.column(c)], 0.0) << c;  // explicit scheme: no viscous loads
}

TEST(ForcesCsv, ImmersedBlockBuoyancyAndTorqueAtAnInterval) {
  core::Comm comm;
  // dt = dt_max = 2 ms in still water: rows at the first step, then at t = 4, 8 ms
  const Csv csv = run_and_read(comm, "still_tank_obstacle", "cases/still_tank_obstacle/case.yaml",
                               {"output/forces_interval=0.004"}, 5);
  ASSERT_EQ(csv.rows.size(), 3u);
  EXPECT_NEAR(csv.rows[0][0], 0.002, 1e-12);
  EXPECT_NEAR(csv.rows[1][0], 0.004, 1e-12);
  EXPECT_NEAR(csv.rows[2][0], 0.008, 1e-12);
  // the block's area and centroid (shoelace)
  const std::vector<double> x{0.06, 0.12, 0.13, 0.07}, z{0.02, 0.01, 0.05, 0.06};
  double A = 0.0, cx = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const std::size_t m = (n + 1) % x.size();
    const double c = x[n] * z[m] - x[m] * z[n];
    A += 0.5 * c;
    cx += (x[n] + x[m]) * c;
  }
  cx /= 6.0 * A;
  const double buoyancy = 1000.0 * 9.81 * A;
  const auto& last = csv.rows.back();
  if (comm.is_root())
    std::printf(
        "immersed block, forces.csv at t = %.4f s: pressure (%.5f, %.5f) N/m against "
        "(0, %.5f); torque %.6f N m/m against rho g A x_c = %.6f\n",
        last[0], last[3], last[4], buoyancy, last[7], buoyancy * cx);
  EXPECT_EQ(last[csv.column("obstacle")], 1.0);
  EXPECT_EQ(last[csv.column("id")], 0.0);
  EXPECT_NEAR(last[csv.column("pressure_z")], buoyancy, 1e-5 * buoyancy);
  EXPECT_NEAR(last[csv.column("pressure_x")], 0.0, 1e-5 * buoyancy);
  EXPECT_NEAR(last[csv.column("torque_pressure")], buoyancy * cx, 1e-5 * buoyancy * cx);
}

// The implicit viscosity (nu = 1e-2, no-slip walls, rigid rows) around the neutral disk in still
// water: the viscous columns are written and hold no load at rest (before gravity was moved after
// the viscous solve, the diffused g dt gave the disk and the walls spurious viscous loads), and the
// pressure force is still rho g A.
TEST(ForcesCsv, NeutralDiskImplicitViscosityNoViscousLoadAtRest) {
  core::Comm comm;
  const Csv csv = run_and_read(comm, "neutral_disk_viscous", "cases/neutral_disk/case.yaml",
                               {"fluid/viscosity=1e-2", "fluid/viscosity_scheme=implicit",
                                "fluid/walls=no_slip", "coupling/viscous_rigid_rows=true"},
                               3);
  ASSERT_EQ(csv.rows.size(), 3u);
  const double buoyancy = 1000.0 * 9.81 * M_PI * 1e-4;
  const auto& last = csv.rows.back();
  if (comm.is_root())
    std::printf(
        "neutral disk, implicit viscosity, forces.csv at t = %.4f s: pressure (%.6f, "
        "%.6f) N/m, viscous (%.3e, %.3e) N/m, viscous torque %.3e N m/m\n",
        last[0], last[3], last[4], last[5], last[6], last[8]);
  EXPECT_NEAR(last[csv.column("pressure_z")], buoyancy, 1e-5 * buoyancy);
  EXPECT_NEAR(last[csv.column("viscous_x")], 0.0, 1e-6 * buoyancy);
  EXPECT_NEAR(last[csv.column("viscous_z")], 0.0, 1e-6 * buoyancy);
  EXPECT_NEAR(last[csv.column("torque_viscous")], 0.0, 1e-9);
}

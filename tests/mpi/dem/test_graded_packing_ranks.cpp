// A graded packing is generated on every rank from its seed, with no communication: on 1 and 3
// ranks every rank holds bitwise the same solids (positions, orientations, masses, inertias).
#include <gtest/gtest.h>

#include "picdem/core/comm.hpp"
#include "picdem/dem/parameters.hpp"

using namespace picdem;

TEST(GradedPackingRanks, EveryRankDrawsTheSamePacking) {
  core::ParamSchema schema;
  schema.real("grid/cell_size", 0.01, "h");
  dem::declare_parameters(schema);
  const std::string text =
      "grid:\n  cell_size: 0.0005\nsolids:\n  rocks:\n    type: graded_packing\n"
      "    density: 2650\n    region: [0, 0, 0.3, 0.6]\n    count: 800\n    placement: pour\n"
      "    seed: 11\n    d_min: 0.003\n    d50: 0.006\n    d_max: 0.02\n"
      "    class_shapes: disk, polygon, ellipse\n    class_densities: [2650, 3000, 8000]\n";
  core::Comm comm;
  const auto s = dem::solids_from(core::read_case_text(text, "case.yaml", {}, schema));
  ASSERT_EQ(s.size(), 800u);
  std::vector<double> mine;
  for (const auto& a : s)
    mine.insert(mine.end(), {a.state.x.x, a.state.x.z, a.state.theta, a.state.mass, a.state.inertia,
                             a.density});
  const auto all = comm.all_gather(mine);
  ASSERT_EQ(all.size(), mine.size() * static_cast<std::size_t>(comm.size()));
  std::size_t differ = 0;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (all[k] != all[k % mine.size()]) ++differ;
  EXPECT_EQ(differ, 0u) << "of " << all.size() << " numbers on " << comm.size() << " ranks";
}

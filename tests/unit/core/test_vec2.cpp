#include <gtest/gtest.h>

#include "picdem/core/rng.hpp"
#include "picdem/core/vec2.hpp"

using picdem::core::IndexBox;
using picdem::core::Vec2;

TEST(Vec2, CrossAndRotate) {
  const Vec2 a{1.0, 0.0}, b{0.0, 2.0};
  EXPECT_DOUBLE_EQ(cross(a, b), 2.0);
  const Vec2 r = rotate(a, M_PI / 2);
  EXPECT_NEAR(r.x, 0.0, 1e-15);
  EXPECT_NEAR(r.z, 1.0, 1e-15);
  const Vec2 w = cross(3.0, Vec2{1.0, 0.0});  // omega x r
  EXPECT_DOUBLE_EQ(w.x, 0.0);
  EXPECT_DOUBLE_EQ(w.z, 3.0);
}

TEST(IndexBox, IntersectAndGrow) {
  const IndexBox a{0, 10, 0, 5}, b{8, 20, 3, 9};
  const IndexBox c = a.intersect(b);
  EXPECT_EQ(c, (IndexBox{8, 10, 3, 5}));
  EXPECT_EQ(c.size(), 4);
  EXPECT_TRUE(a.intersect(IndexBox{10, 12, 0, 5}).empty());
  EXPECT_EQ(a.grown(2), (IndexBox{-2, 12, -2, 7}));
}

TEST(Rng, CounterBasedIsDeterministicAndUniform) {
  EXPECT_EQ(picdem::core::uniform01(1, 2, 3), picdem::core::uniform01(1, 2, 3));
  double mean = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) mean += picdem::core::uniform01(7, static_cast<unsigned>(i));
  mean /= n;
  // Standard error of the mean of U(0,1) is 0.29/sqrt(n) = 9e-4: 5 sigma.
  EXPECT_NEAR(mean, 0.5, 4.6e-3);
}

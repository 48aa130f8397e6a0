// The terrain relief under the last stretch of path decides where the moving-echo filter runs.

#include "reconstruct/terrain_relief.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace littermap::reconstruct {
namespace {

TEST(TerrainRelief, SpreadOfTheHeightOverTheLastWindowOfPath) {
  TerrainRelief relief(10);
  EXPECT_DOUBLE_EQ(relief.Add({0, 0, 0}, 0.0), 0.0);
  // Up 0.5 m over the first 5 m, then level.
  double last = 0;
  for (int i = 1; i <= 50; ++i) last = relief.Add({0.1 * i, 0, 0}, 0.1 * std::min(i, 5));
  EXPECT_NEAR(last, 0.5, 1e-12);
  // 10 m further on level ground the climb has left the window.
  for (int i = 51; i <= 200; ++i) last = relief.Add({0.1 * i, 0, 0}, 0.5);
  EXPECT_NEAR(last, 0.0, 1e-12);
}

TEST(TerrainRelief, TurningOnTheSpotIsNoPath) {
  TerrainRelief relief(1);
  relief.Add({0, 0, 0}, 0.0);
  double last = 0;
  for (int i = 0; i < 100; ++i) last = relief.Add({0, 0, 0.1 * i}, i == 99 ? 0.3 : 0.0);
  EXPECT_NEAR(last, 0.3, 1e-12);  // every sample is within 1 m of path
}

}  // namespace
}  // namespace littermap::reconstruct

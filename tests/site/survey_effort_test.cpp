#include "site/survey_effort.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace littermap::site {
namespace {

heatmap::GridGeometry Grid(double size_m, double cell_m) {
  heatmap::GridGeometry grid;
  grid.min_x_m = 0.0;
  grid.max_y_m = size_m;
  grid.cell_size_m = cell_m;
  grid.width = grid.height = static_cast<int>(std::lround(size_m / cell_m));
  return grid;
}

TEST(SurveyEffort, GroundSectorFollowsTheMount) {
  CameraFootprintOptions options;
  options.mount_height_m = 0.6;
  options.vertical_fov_deg = 45.0;  // 25 deg down: rays from 2.5 to 47.5 deg below the horizon
  const FootprintSector sector = GroundSector(options);
  EXPECT_NEAR(sector.near_m, 0.6 / std::tan(47.5 * std::numbers::pi / 180.0), 1e-9);
  EXPECT_DOUBLE_EQ(sector.far_m, 4.0);
  options.mount_pitch_down_deg = 40.0;  // steeper: the far edge is the shallowest ray
  EXPECT_NEAR(GroundSector(options).far_m, 0.6 / std::tan(17.5 * std::numbers::pi / 180.0), 1e-9);
  options.mount_pitch_down_deg = -30.0;  // looking at the sky
  EXPECT_THROW(GroundSector(options), UsageError);
}

TEST(SurveyEffort, StraightRunCoversAStripAheadOfTheCamera) {
  const heatmap::GridGeometry grid = Grid(40.0, 0.5);
  CameraFootprintOptions options;
  options.horizontal_fov_deg = 90.0;
  options.mount_x_m = 0.0;
  const std::vector<PlanarPose> run = {{5.0, 20.0, 0.0}, {25.0, 20.0, 0.0}};
  const RunCoverage coverage = CoverRun(grid, run, options);
  auto observed = [&](double x, double y) {
    const int c = static_cast<int>(x / grid.cell_size_m);
    const int r = static_cast<int>((grid.max_y_m - y) / grid.cell_size_m);
    return coverage.observed[static_cast<std::size_t>(r) * grid.width + c] == 1;
  };
  EXPECT_TRUE(observed(15.2, 20.2));   // on the path
  EXPECT_TRUE(observed(28.2, 20.2));   // ahead of the last pose, within 4 m
  EXPECT_FALSE(observed(30.2, 20.2));  // beyond detection range
  EXPECT_FALSE(observed(4.2, 20.2));   // behind the first pose
  EXPECT_TRUE(observed(15.2, 22.7));   // 2.5 m to the side: seen from a pose 2.5+ m back
  EXPECT_FALSE(observed(15.2, 24.7));  // 4.5 m to the side: never within range
  // Area: a 20 m strip of width 2 x 2.83 m (45 deg half-angle at 4 m) plus the end sector.
  EXPECT_GT(coverage.observed_area_m2, 20.0 * 5.0);
  EXPECT_LT(coverage.observed_area_m2, 20.0 * 8.0 + 4.0 * 4.0 * std::numbers::pi / 4.0);
  heatmap::Raster effort(grid, 0.0f);
  AddCoverage(effort, coverage);
  AddCoverage(effort, coverage);
  EXPECT_EQ(effort.at(30, 39), 2.0f);  // a cell seen by both runs counts two surveys
  float max_effort = 0.0f;
  for (float v : effort.values) max_effort = std::max(max_effort, v);
  EXPECT_EQ(max_effort, 2.0f);  // many footprints of one run still count once
}

}  // namespace
}  // namespace littermap::site

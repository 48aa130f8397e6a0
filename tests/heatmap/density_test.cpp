// Kernel density, survey effort and their ratio on synthetic cases with known answers.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "heatmap/density_map.hpp"
#include "heatmap/kernel_density.hpp"

namespace littermap::heatmap {
namespace {

GridGeometry Grid(double size_m, double cell_m) {
  GridGeometry grid;
  grid.min_x_m = 0.0;
  grid.max_y_m = size_m;
  grid.cell_size_m = cell_m;
  grid.width = grid.height = static_cast<int>(std::lround(size_m / cell_m));
  return grid;
}

double Sum(const Raster& raster, double scale) {
  double sum = 0.0;
  for (float v : raster.values) sum += v * scale;
  return sum;
}

TEST(KernelDensity, SingleItemHasTheQuarticPeak) {
  const GridGeometry grid = Grid(20.0, 0.25);
  const std::vector<db::PointXY> item = {{10.125, 10.125}};  // a cell centre
  const KernelDensityResult result = KernelDensity(grid, item, {3.0});
  const double peak = 3.0 / (std::numbers::pi * 9.0);  // K(0) = 3 / (pi h^2)
  // Sampled at 0.25 m the discrete kernel sums to within 1 % of the continuous one.
  EXPECT_NEAR(result.density.at(40, 39), peak, 0.01 * peak);
  EXPECT_EQ(result.density.at(40 + 13, 39), 0.0f);  // 3.25 m away: beyond h
  EXPECT_NEAR(Sum(result.density, grid.cell_area_m2()), 1.0, 1e-6);
}

TEST(KernelDensity, RefusesANonPositiveBandwidth) {
  EXPECT_THROW(KernelDensity(Grid(10, 1), {}, {0.0}), UsageError);
}

TEST(DensityMap, IntegratesBackToTheItemCountWhereEffortIsUniform) {
  // 5000 items scattered in the middle of a 200 m square surveyed three times everywhere.
  const GridGeometry grid = Grid(200.0, 0.5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(20.0, 180.0);
  std::vector<db::PointXY> items(5000);
  for (auto& p : items) p = {coordinate(random), coordinate(random)};
  const Raster effort(grid, 3.0f);
  const DensityMapResult result = EffortNormalisedDensity(effort, items, {});
  // items per 100 m^2 per survey x surveys x cell area / 100 m^2 = items.
  const double count = Sum(result.density, 3.0 * grid.cell_area_m2() / 100.0);
  EXPECT_NEAR(count, 5000.0, 0.01 * 5000.0);
  EXPECT_EQ(result.items_used, 5000u);
  EXPECT_EQ(result.surveyed_cells, grid.size());
}

TEST(DensityMap, UnsurveyedCellsAreNodataNotZero) {
  const GridGeometry grid = Grid(20.0, 1.0);
  Raster effort(grid, 0.0f);
  for (int r = 0; r < 20; ++r) {
    for (int c = 0; c < 10; ++c) effort.at(c, r) = 2.0f;  // western half surveyed twice
  }
  const std::vector<db::PointXY> items = {{5.0, 10.0}};
  DensityMapOptions options;
  const DensityMapResult result = EffortNormalisedDensity(effort, items, options);
  EXPECT_EQ(result.density.at(15, 10), options.nodata);
  EXPECT_EQ(result.density.at(2, 2), 0.0f);  // surveyed, nothing found
  EXPECT_GT(result.density.at(4, 9), 0.0f);
  EXPECT_EQ(result.surveyed_cells, 200u);
  EXPECT_DOUBLE_EQ(result.surveyed_area_m2, 200.0);
}

TEST(DensityMap, NoBiasAtTheBorderOfUnequalEffort) {
  // Litter on a 1 m lattice everywhere (1 item per m^2 = 100 per 100 m^2). The west half was
  // surveyed once, the east half twice, so east items were detected twice.
  const GridGeometry grid = Grid(60.0, 0.5);
  Raster effort(grid, 0.0f);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) effort.at(c, r) = c < grid.width / 2 ? 1.0f : 2.0f;
  }
  std::vector<db::PointXY> detections;
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 60; ++x) {
      const db::PointXY p{x + 0.5, y + 0.5};
      detections.push_back(p);
      if (x >= 30) detections.push_back(p);
    }
  }
  const DensityMapResult result = EffortNormalisedDensity(effort, detections, {});
  // Away from the grid's outer edge (where the kernel leaves the grid), every cell, including
  // those next to the effort border at x = 30 m, reads 100 within 2 %.
  for (int r = 20; r < 100; ++r) {
    for (int c = 20; c < 100; ++c) {
      ASSERT_NEAR(result.density.at(c, r), 100.0f, 2.0f) << "cell " << c << "," << r;
    }
  }
}

TEST(KernelDensity, SmoothingKeepsAUniformRaster) {
  const Raster uniform(Grid(30.0, 0.5), 3.0f);
  const Raster smoothed = KernelSmooth(uniform, {3.0});
  EXPECT_NEAR(smoothed.at(30, 30), 3.0f, 1e-5f);
  EXPECT_LT(smoothed.at(0, 0), 3.0f);  // outside the grid counts as unsurveyed
}

TEST(KernelDensity, AReachBeyondTwoHundredCellsIsRefusedNotOverflowed) {
  const Raster uniform(Grid(30.0, 0.5), 3.0f);
  EXPECT_NO_THROW(KernelSmooth(uniform, {100.0}));  // 200 cells
  EXPECT_THROW(KernelSmooth(uniform, {100.5}), UsageError);
  EXPECT_THROW(KernelSmooth(uniform, {1e12}), UsageError);  // was a reach past INT_MAX
}

}  // namespace
}  // namespace littermap::heatmap

// density.png draws the site map over the density: a wall of the map shows as ink on the
// pixels it covers, ground the map knows but no run surveyed is lighter than the unknown.

#include "heatmap/density_preview.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "support/temp_dir.hpp"

namespace littermap::heatmap {
namespace {

TEST(DensityPreview, DrawsTheSiteMapOverTheDensity) {
  test::TempDir dir;
  GridGeometry grid;
  grid.min_x_m = 0;
  grid.max_y_m = 20;
  grid.cell_size_m = 0.5;
  grid.width = 40;
  grid.height = 40;
  const float nodata = -1;
  Raster density(grid, 0.0f);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 20; c < grid.width; ++c) density.at(c, r) = nodata;  // east half unsurveyed
  }
  density.at(5, 5) = 2.0f;
  DensityPreviewOptions options;
  options.max_size_px = 400;  // 10 px per cell
  // A wall along x = 5 m, everything else free ground, mapped only up to x = 15 m.
  options.occupancy = [](double x, double) -> std::optional<std::uint8_t> {
    if (x > 15) return std::nullopt;
    return std::abs(x - 5) < 0.05 ? 0 : 254;
  };
  WriteDensityPreview(dir / "density.png", density, nodata, options);
  const cv::Mat png = cv::imread((dir / "density.png").string());
  ASSERT_FALSE(png.empty());
  const int top = 36;  // title band
  const auto at = [&](double x, double y) {
    return png.at<cv::Vec3b>(top + static_cast<int>((20 - y) * 20), static_cast<int>(x * 20));
  };
  EXPECT_EQ(at(5.0, 10), cv::Vec3b(255, 255, 255)) << "wall on dark density: white ink";
  EXPECT_NE(at(7.0, 10), cv::Vec3b(255, 255, 255)) << "free ground keeps its colour";
  EXPECT_EQ(at(12.5, 10), cv::Vec3b(238, 238, 238)) << "mapped, not surveyed";
  EXPECT_EQ(at(17.5, 10), cv::Vec3b(215, 215, 215)) << "neither mapped nor surveyed";
}

}  // namespace
}  // namespace littermap::heatmap

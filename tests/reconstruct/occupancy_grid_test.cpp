// Occupancy grid: the ray traversal visits every cell a segment crosses (checked against dense
// sampling), log-odds clamping, and the map_server files.

#include "reconstruct/occupancy_grid.hpp"

#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

using CellSet = std::set<std::pair<std::int64_t, std::int64_t>>;

TEST(OccupancyGrid, RayTraversalVisitsEveryCrossedCellOnceInOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  const double cell = 0.1;
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector2d a(coordinate(random), coordinate(random));
    const Eigen::Vector2d b(coordinate(random), coordinate(random));
    std::vector<CellIndex> visited;
    TraverseRay(a, b, cell, [&](CellIndex c) { visited.push_back(c); });
    CellSet traversed;
    for (std::size_t i = 0; i < visited.size(); ++i) {
      traversed.insert({visited[i].x, visited[i].y});
      if (i > 0) {  // 4-connected steps: no cell skipped diagonally
        EXPECT_EQ(
            std::abs(visited[i].x - visited[i - 1].x) + std::abs(visited[i].y - visited[i - 1].y),
            1);
      }
    }
    EXPECT_EQ(traversed.size(), visited.size()) << "a cell visited twice";
    EXPECT_EQ(visited.front(),
              (CellIndex{CellCoordinate(a.x(), cell), CellCoordinate(a.y(), cell)}));
    EXPECT_EQ(visited.back(),
              (CellIndex{CellCoordinate(b.x(), cell), CellCoordinate(b.y(), cell)}));
    // Dense sampling (1 um steps would be exact; 1e-4 of the length misses only cells the
    // segment clips by less than that, which traversal must still contain).
    const int samples = 20000;
    for (int s = 0; s <= samples; ++s) {
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(s) / samples);
      const std::pair<std::int64_t, std::int64_t> c{CellCoordinate(p.x(), cell),
                                                    CellCoordinate(p.y(), cell)};
      EXPECT_TRUE(traversed.count(c)) << "missed cell " << c.first << "," << c.second;
    }
  }
}

TEST(OccupancyGrid, LogOddsAreClampedBothWays) {
  OccupancyGridOptions options;
  options.cell_size_m = 0.1;
  OccupancyGrid grid(options);
  const Eigen::Vector2d origin(0.05, 0.05);
  const Points2 hits = {{2.05, 0.05}};
  grid.InsertScan(origin, hits);
  EXPECT_FLOAT_EQ(grid.LogOdds(grid.CellOf(hits[0])), static_cast<float>(options.log_odds_hit));
  EXPECT_FLOAT_EQ(grid.LogOdds(grid.CellOf({1.05, 0.05})),
                  static_cast<float>(options.log_odds_miss));
  for (int i = 0; i < 100; ++i) grid.InsertScan(origin, hits);
  EXPECT_FLOAT_EQ(grid.LogOdds(grid.CellOf(hits[0])), static_cast<float>(options.log_odds_max));
  EXPECT_FLOAT_EQ(grid.LogOdds(grid.CellOf({1.05, 0.05})),
                  static_cast<float>(options.log_odds_min));
  EXPECT_FLOAT_EQ(grid.LogOdds(grid.CellOf({2.55, 0.05})), 0.0f);  // beyond the hit: unknown
}

TEST(OccupancyGrid, WritesMapServerPgmAndYaml) {
  OccupancyGridOptions options;
  options.cell_size_m = 0.1;
  OccupancyGrid grid(options);
  for (int i = 0; i < 5; ++i) grid.InsertScan({0.05, 0.05}, {{1.05, 0.05}, {0.05, 1.05}});
  test::TempDir dir;
  grid.WritePgmYaml(dir / "map.pgm", dir / "map.yaml");
  grid.WritePng(dir / "map.png");
  std::ifstream pgm(dir / "map.pgm", std::ios::binary);
  std::string magic;
  pgm >> magic;
  EXPECT_EQ(magic, "P5");
  std::ifstream yaml(dir / "map.yaml");
  const std::string text((std::istreambuf_iterator<char>(yaml)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("image: map.pgm"), std::string::npos);
  EXPECT_NE(text.find("resolution: 0.1"), std::string::npos);
  EXPECT_NE(text.find("occupied_thresh: 0.65"), std::string::npos);
  EXPECT_TRUE(std::filesystem::file_size(dir / "map.png") > 0);
}

}  // namespace
}  // namespace littermap::reconstruct

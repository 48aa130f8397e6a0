// The acceptance check, with a synthetic park instead of the simulator: three runs with
// different routes over one park ingest into one site, and the effort-normalised density
// correlates with the true litter density on the surveyed cells (Pearson r >= 0.8). Every item
// the camera covered is detected (a perfect detector), so what is tested is the effort
// normalisation across unequal, overlapping coverage.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "heatmap/heatmap_files.hpp"
#include "heatmap/kernel_density.hpp"
#include "heatmap/site_heatmap.hpp"
#include "sim/simulation.hpp"
#include "sim/world_spec.hpp"
#include "site/run_ingest.hpp"
#include "support/temp_dir.hpp"

namespace littermap::heatmap {
namespace {

// 10 cm steps along the waypoints, heading along each leg.
std::vector<PlanarPose> Route(const std::vector<db::PointXY>& waypoints) {
  std::vector<PlanarPose> poses;
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
    const db::PointXY a = waypoints[i], b = waypoints[i + 1];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const double yaw = std::atan2(b.y - a.y, b.x - a.x);
    const int steps = static_cast<int>(length / 0.1);
    for (int s = 0; s < steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      poses.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), yaw});
    }
  }
  return poses;
}

// A 40 x 30 m park: three litter clusters (around a bench, a bin, a path edge) and a scatter.
std::vector<site::RunItem> ParkLitter() {
  std::mt19937 random(11);
  std::normal_distribution<double> spread(0.0, 2.0);
  std::uniform_real_distribution<double> x(1.0, 39.0), y(1.0, 29.0);
  const db::PointXY centres[] = {{10, 8}, {30, 20}, {20, 15}};
  std::vector<site::RunItem> items;
  for (const db::PointXY& centre : centres) {
    for (int i = 0; i < 40; ++i) {
      items.push_back({std::to_string(items.size()),
                       "can",
                       {centre.x + spread(random), centre.y + spread(random)},
                       0,
                       0.1,
                       1});
    }
  }
  for (int i = 0; i < 30; ++i) {
    items.push_back({std::to_string(items.size()), "cup", {x(random), y(random)}, 0, 0.1, 1});
  }
  return items;
}

double Pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(SiteHeatmap, ThreeRunsCorrelateWithTheTrueDensity) {
  littermap::test::TempDir dir;
  db::SiteOptions site_options;
  site_options.name = "synthetic park";
  db::SiteDatabase site = db::SiteDatabase::Create(dir / "park.gpkg", site_options);
  const std::vector<site::RunItem> litter = ParkLitter();
  const std::vector<std::vector<db::PointXY>> routes = {
      {{4, 4}, {36, 4}, {36, 26}, {4, 26}, {4, 8}},                                // loop
      {{3, 6}, {37, 6}, {37, 12}, {3, 12}, {3, 18}, {37, 18}, {37, 24}, {3, 24}},  // mower
      {{2, 2}, {12, 28}, {20, 2}, {28, 28}, {38, 2}, {38, 15}, {2, 15}}};          // zigzag
  site::IngestOptions options;
  options.drop_unobserved_items = true;  // the camera only finds what it covered
  for (std::size_t i = 0; i < routes.size(); ++i) {
    site::RunInput run;
    run.name = run.source_digest = "run" + std::to_string(i);
    run.start_time_s = 1000.0 * static_cast<double>(i);
    run.T_site_base = Route(routes[i]);
    run.items = litter;
    site::IngestRun(site, run, options);
  }
  const SiteHeatmap map = ComputeSiteHeatmap(site, {});
  std::vector<db::PointXY> truth;
  for (const site::RunItem& item : litter) truth.push_back(item.xy);
  const Raster true_density = KernelDensity(map.effort.grid, truth, {3.0}).density;

  std::vector<double> estimated, expected;
  float max_effort = 0.0f;
  for (std::size_t i = 0; i < map.effort.values.size(); ++i) {
    max_effort = std::max(max_effort, map.effort.values[i]);
    if (map.effort.values[i] < 1.0f) continue;
    estimated.push_back(map.density.density.values[i]);
    expected.push_back(100.0 * true_density.values[i]);  // items per 100 m^2, litter is static
  }
  EXPECT_EQ(max_effort, 3.0f);  // the routes overlap
  const double r = Pearson(estimated, expected);
  RecordProperty("pearson_r", std::to_string(r));
  EXPECT_GE(r, 0.8) << "over " << estimated.size() << " surveyed cells";
  std::printf("pearson_r %.3f over %zu surveyed cells\n", r, estimated.size());
}

// --min-confidence: detections less sure than the threshold are left out of the density, the
// items and the hotspots, and the hotspots of a threshold are stored apart from those of all.
TEST(SiteHeatmap, AMinimumConfidenceLeavesOutTheLessSureDetections) {
  littermap::test::TempDir dir;
  db::SiteOptions site_options;
  site_options.name = "confidence park";
  db::SiteDatabase site = db::SiteDatabase::Create(dir / "park.gpkg", site_options);
  site::RunInput run;
  run.name = run.source_digest = "run";
  run.T_site_base = Route({{0, 10}, {40, 10}});
  for (int i = 0; i < 4; ++i) {  // four sure cans at x = 10, four unsure cups at x = 30
    run.items.push_back({"can" + std::to_string(i), "can", {9.0 + i, 10.5}, 0, 0.1, 0.9});
    run.items.push_back({"cup" + std::to_string(i), "cup", {29.0 + i, 10.5}, 0, 0.1, 0.3});
  }
  site::IngestRun(site, run, {});

  SiteHeatmapOptions options;
  const SiteHeatmap all = ComputeSiteHeatmap(site, options);
  EXPECT_EQ(all.items.size(), 8u);
  EXPECT_EQ(all.detections, 8u);
  options.min_confidence = 0.5;
  const SiteHeatmap sure = ComputeSiteHeatmap(site, options);
  EXPECT_EQ(sure.items.size(), 4u);
  EXPECT_EQ(sure.detections, 4u);
  for (const db::ItemRecord& item : sure.items) EXPECT_EQ(item.class_name, "can");
  const GridGeometry& grid = sure.density.density.grid;
  const int row = static_cast<int>((grid.max_y_m - 10.5) / grid.cell_size_m);
  const auto column = [&](double x) {
    return static_cast<int>((x - grid.min_x_m) / grid.cell_size_m);
  };
  EXPECT_GT(sure.density.density.at(column(10.5), row), 0.0f);
  EXPECT_EQ(sure.density.density.at(column(30.5), row), 0.0f);
  EXPECT_GT(all.density.density.at(column(30.5), row), 0.0f);
  options.min_confidence = 0.95;
  EXPECT_TRUE(ComputeSiteHeatmap(site, options).items.empty());
  options.min_confidence = 1.5;
  EXPECT_THROW(ComputeSiteHeatmap(site, options), UsageError);

  HeatmapFilesOptions files;
  files.map.min_confidence = 0.5;
  EXPECT_EQ(WriteHeatmapFiles(site, dir / "sure", files).hotspots, 1u);
  files.map.min_confidence = 0.0;
  EXPECT_EQ(WriteHeatmapFiles(site, dir / "all", files).hotspots, 2u);
  files.map.min_confidence = 0.5;
  WriteHeatmapFiles(site, dir / "sure", files);  // replaces only the threshold's own
  const auto stored = site.sql().Prepare(
      "SELECT filter_min_confidence, count(*) FROM hotspots GROUP BY 1 ORDER BY 1");
  std::vector<std::pair<std::string, std::int64_t>> counts;
  while (stored->Step()) counts.emplace_back(stored->ColumnText(0), stored->ColumnInt64(1));
  EXPECT_EQ(counts, (std::vector<std::pair<std::string, std::int64_t>>{{"", 2}, {"0.5", 1}}));
}

// The same check on the simulator: park_large surveyed three times from its dock, along its
// three routes with three run seeds. Items are the world's litter the camera covered (a perfect
// detector); the truth is the kernel density of all the world's litter.
TEST(SiteHeatmap, ThreeSimulatorRunsOfOneParkCorrelateWithItsLitter) {
  littermap::test::TempDir dir;
  db::SiteOptions site_options;
  site_options.name = "park_large";
  db::SiteDatabase site = db::SiteDatabase::Create(dir / "park.gpkg", site_options);
  sim::WorldSpec spec = sim::LoadWorldSpec(std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" /
                                           "worlds" / "park_large.yaml");
  std::vector<db::PointXY> truth;
  site::IngestOptions options;
  options.drop_unobserved_items = true;
  const char* routes[] = {"", "perimeter", "diagonals"};
  for (std::uint64_t run = 0; run < 3; ++run) {
    spec.driven_route = routes[run];
    spec.run_seed = run + 1;
    const sim::Simulation simulation(spec);
    site::RunInput input;
    input.name = input.source_digest = std::string("run-") + std::to_string(run);
    input.start_time_s = 100000.0 * static_cast<double>(run);
    for (const sim::RobotState& state : simulation.states()) {
      input.T_site_base.push_back(state.pose);
    }
    std::vector<db::PointXY> litter;
    for (const sim::WorldObject& o : simulation.world().objects) {
      if (o.kind != sim::ObjectKind::kLitter) continue;
      input.items.push_back({std::to_string(o.id),
                             o.label,
                             {o.center_m.x(), o.center_m.y()},
                             o.center_m.z(),
                             o.size(),
                             1.0});
      litter.push_back({o.center_m.x(), o.center_m.y()});
    }
    if (run == 0) truth = litter;
    EXPECT_EQ(litter.size(), truth.size()) << "one park";
    site::IngestRun(site, input, options);
  }
  const SiteHeatmap map = ComputeSiteHeatmap(site, {});
  const Raster true_density = KernelDensity(map.effort.grid, truth, {3.0}).density;
  std::vector<double> estimated, expected;
  for (std::size_t i = 0; i < map.effort.values.size(); ++i) {
    if (map.effort.values[i] < 1.0f) continue;
    estimated.push_back(map.density.density.values[i]);
    expected.push_back(100.0 * true_density.values[i]);
  }
  const double r = Pearson(estimated, expected);
  RecordProperty("pearson_r", std::to_string(r));
  EXPECT_GE(r, 0.8) << "over " << estimated.size() << " surveyed cells";
  std::printf("pearson_r %.3f over %zu surveyed cells, %zu litter items\n", r, estimated.size(),
              truth.size());
}

}  // namespace
}  // namespace littermap::heatmap

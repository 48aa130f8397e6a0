// Effort-normalised kernel density (issue 7 speed goal): 1 million items into a 2000 x 2000
// raster (0.5 m cells, a 1 km square) with the default 3 m quartic kernel, divided by a survey
// effort raster. Goal: <= 5 s on one core.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bench/lawn_mower.hpp"
#include "heatmap/density_map.hpp"
#include "site/survey_effort.hpp"

namespace {

using littermap::heatmap::DensityMapOptions;
using littermap::heatmap::GridGeometry;
using littermap::heatmap::Raster;

GridGeometry BenchGrid() {
  GridGeometry grid;
  grid.min_x_m = 0.0;
  grid.max_y_m = 1000.0;
  grid.cell_size_m = 0.5;
  grid.width = grid.height = 2000;
  return grid;
}

void BM_EffortNormalisedDensity(benchmark::State& state) {
  const GridGeometry grid = BenchGrid();
  const auto count = static_cast<std::size_t>(state.range(0));
  std::mt19937 random(42);
  std::uniform_real_distribution<double> coordinate(0.0, 1000.0);
  std::vector<littermap::db::PointXY> items(count);
  for (auto& p : items) p = {coordinate(random), coordinate(random)};
  // Effort from 1 to 4 surveys in bands, a quarter of the site unsurveyed.
  Raster effort(grid, 0.0f);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = grid.width / 4; c < grid.width; ++c)
      effort.at(c, r) = static_cast<float>(1 + r % 4);
  }
  for (auto _ : state) {
    auto result = littermap::heatmap::EffortNormalisedDensity(effort, items, DensityMapOptions{});
    benchmark::DoNotOptimize(result.density.values.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
}
BENCHMARK(BM_EffortNormalisedDensity)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SurveyEffortOneRun(benchmark::State& state) {
  const GridGeometry grid = BenchGrid();
  // A 15-minute run at 0.5 m/s sampled at 10 Hz: a lawn-mower pattern, 9000 poses.
  const std::vector<littermap::PlanarPose> run =
      littermap::bench::LawnMowerRun(100.0, 100.0, 100.0);
  for (auto _ : state) {
    auto coverage = littermap::site::CoverRun(grid, run, {});
    benchmark::DoNotOptimize(coverage.observed.data());
  }
}
BENCHMARK(BM_SurveyEffortOneRun)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

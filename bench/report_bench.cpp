// The site report (issue 8): figures, site map, close-ups, index.html and report.json of a
// park surveyed N times. A 100 x 60 m park, each run a 15-minute lawn-mower survey (9000 poses)
// finding 150 items, 60 % of them items earlier runs found. Goal: a season of 50 runs in
// <= 10 s on one core, so `survey` and `report` stay interactive.

#include <benchmark/benchmark.h>

#include <unistd.h>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "bench/lawn_mower.hpp"
#include "reports/report_files.hpp"
#include "site/run_ingest.hpp"

namespace {

namespace fs = std::filesystem;

fs::path SurveyedSite(int runs) {
  const fs::path file =
      fs::temp_directory_path() /
      ("littermap-report-bench-" + std::to_string(getpid()) + "-" + std::to_string(runs) + ".gpkg");
  fs::remove(file);
  littermap::db::SiteOptions options;
  options.name = "Bench park";
  options.epsg_code = 32632;
  options.origin_easting_m = 691000;
  options.origin_northing_m = 5334000;
  auto site = littermap::db::SiteDatabase::Create(file, options);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(5, 95), y(3, 57), unit(0, 1);
  std::normal_distribution<double> jitter(0, 0.2);
  const char* classes[] = {"bottle", "can", "cup", "carton", "food_container", "plastic_bag"};
  std::vector<littermap::db::PointXY> litter;
  for (int r = 0; r < runs; ++r) {
    littermap::site::RunInput run;
    run.name = "run " + std::to_string(r + 1);
    run.source_digest = "bench-" + std::to_string(r);
    run.start_time_s = 1.79e9 + r * 7 * 86400.0;
    run.end_time_s = run.start_time_s + 900;
    run.T_site_base = littermap::bench::LawnMowerRun(5.0, 3.0, 90.0);
    for (int i = 0; i < 150; ++i) {
      littermap::db::PointXY p{x(random), y(random)};
      if (!litter.empty() && unit(random) < 0.6) {
        p = litter[static_cast<std::size_t>(unit(random) * static_cast<double>(litter.size()))];
      } else {
        litter.push_back(p);
      }
      run.items.push_back({std::to_string(i),
                           classes[i % 6],
                           {p.x + jitter(random), p.y + jitter(random)},
                           0,
                           0.1,
                           0.9});
    }
    littermap::site::IngestRun(site, run, {});
  }
  return file;
}

void BM_SiteReport(benchmark::State& state) {
  const int runs = static_cast<int>(state.range(0));
  const fs::path file = SurveyedSite(runs);
  const fs::path dir = file.string() + ".report";
  auto site = littermap::db::SiteDatabase::Open(file);
  littermap::reports::SiteReport report;
  for (auto _ : state) {
    report = littermap::reports::WriteReportFiles(site, dir, {});
    benchmark::DoNotOptimize(report.items);
  }
  state.counters["runs"] = runs;
  state.counters["items"] = static_cast<double>(report.items);
  state.counters["html_MB"] = static_cast<double>(fs::file_size(dir / "index.html")) / 1e6;
  fs::remove_all(dir);
  fs::remove(file);
  fs::remove(file.string() + "-wal");
  fs::remove(file.string() + "-shm");
}
BENCHMARK(BM_SiteReport)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();

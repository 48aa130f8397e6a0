// A city park after years of surveys, on both engines: 1,000 runs and 1,000,000 litter items in
// one site, then the three things a new survey does to it, timed: ingest the next run, heatmap,
// report. Goal (issue 34): each within 2 s / 10 s / 10 s on one core, PostGIS and GeoPackage
// side by side.
//   site_scale_bench [--runs N] [--items-per-run N] [--postgis URL] [--keep DIR [--reuse]]
// --keep keeps the sites (DIR/scale.gpkg, schema scale_bench); --reuse times the three steps on
// the sites kept before instead of building them again (each time one more run is ingested).
// The park is 1,000 m x N m: run r drives east along y = r + 0.5 m at 0.5 m/s (2 poses a second)
// and finds items on a 1 m lattice half a metre to its left, so no item is another's (the
// same-item radius is 0.75 m) and the site ends with runs x items-per-run items. The next run
// drives row N/2 again and finds every item there: all seen again. Without --postgis, only the
// GeoPackage column is filled (scripts/postgis.sh start gives a URL).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "heatmap/heatmap_files.hpp"
#include "reports/report_files.hpp"
#include "site/run_ingest.hpp"

namespace {

namespace fs = std::filesystem;
using namespace littermap;

site::RunInput Row(int row, int items, int run_index) {
  site::RunInput run;
  run.name = "run " + std::to_string(run_index + 1);
  run.source_digest = "scale-" + std::to_string(run_index);
  run.start_time_s = 1.6e9 + run_index * 86400.0;
  const double length_m = items * 1.0;
  run.end_time_s = run.start_time_s + length_m / 0.5;
  for (double x = 0; x <= length_m; x += 0.25) run.T_site_base.push_back({x, row + 0.5, 0.0});
  const char* classes[] = {"bottle", "can", "cup", "carton", "food_container", "plastic_bag"};
  for (int i = 0; i < items; ++i) {
    run.items.push_back(
        {std::to_string(i), classes[(i + row) % 6], {i + 0.5, row + 1.0}, 0.0, 0.1, 0.9});
  }
  return run;
}

double Seconds(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Column {
  std::string engine;
  double build_s = -1, ingest_s = 0, heatmap_s = 0, report_s = 0;  // build_s < 0: kept from before
  std::size_t items = 0;
};

// Ingests one more run (row N/2 again) into the site and times it, the heatmap and the report.
Column MeasureNextRun(Column column, const db::SiteLocator& where, int runs, int items,
                      const fs::path& dir) {
  db::SiteDatabase site = db::SiteDatabase::Open(where);
  const int next = static_cast<int>(site.Runs().size());
  column.ingest_s = Seconds([&] { site::IngestRun(site, Row(runs / 2, items, next), {}); });
  column.heatmap_s = Seconds([&] {
    heatmap::HeatmapFilesOptions heatmap;
    heatmap.force_output = true;
    heatmap::WriteHeatmapFiles(site, dir / (column.engine + "-maps"), heatmap);
  });
  column.report_s = Seconds([&] {
    reports::ReportFilesOptions report;
    report.force_output = true;
    reports::WriteReportFiles(site, dir / (column.engine + "-report"), report);
  });
  column.items = site.Items().size();
  return column;
}

Column Measure(const std::string& engine, const db::SiteLocator& where, int runs, int items,
               const fs::path& dir, bool reuse) {
  Column column;
  column.engine = engine;
  if (reuse && db::SiteDatabase::Exists(where))
    return MeasureNextRun(column, where, runs, items, dir);
  db::SiteDatabase::Remove(where);
  db::SiteOptions options;
  options.name = "Scale park";
  options.epsg_code = 32632;
  options.origin_easting_m = 690000;
  options.origin_northing_m = 5330000;
  db::SiteDatabase::Create(where, options);
  column.build_s = Seconds([&] {
    db::SiteDatabase site = db::SiteDatabase::Open(where);
    for (int r = 0; r < runs; ++r) {
      site::IngestRun(site, Row(r, items, r), {});
      if ((r + 1) % 50 == 0) {
        std::fprintf(stderr, "%s: %d of %d runs\n", engine.c_str(), r + 1, runs);
      }
    }
  });
  return MeasureNextRun(column, where, runs, items, dir);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 1000, items = 1000;
  std::string postgis;
  fs::path dir = fs::temp_directory_path() / ("littermap-scale-" + std::to_string(getpid()));
  bool keep = false, reuse = false;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : "";
    if (key == "--reuse") reuse = true;
    if (key == "--runs") runs = std::atoi(value);
    if (key == "--items-per-run") items = std::atoi(value);
    if (key == "--postgis") postgis = value;
    if (key == "--keep") keep = true, dir = value;
  }
  fs::create_directories(dir);
  std::vector<Column> columns;
  try {
    columns.push_back(Measure("GeoPackage", dir / "scale.gpkg", runs, items, dir, reuse));
    if (!postgis.empty()) {
      columns.push_back(Measure("PostGIS", db::ParseSiteLocator(postgis + "?site=scale_bench"),
                                runs, items, dir, reuse));
      if (!keep) db::SiteDatabase::Remove(db::ParseSiteLocator(postgis + "?site=scale_bench"));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "site_scale_bench: %s\n", e.what());
    return 1;
  }
  std::printf("%d runs, %d items each\n\n| | goal |", runs, items);
  for (const Column& c : columns) std::printf(" %s |", c.engine.c_str());
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < columns.size(); ++i) std::printf("---|");
  const auto row = [&](const char* name, const char* goal, double Column::*field) {
    std::printf("\n| %s | %s |", name, goal);
    for (const Column& c : columns) {
      if (c.*field < 0) {
        std::printf(" kept from before |");
      } else {
        std::printf(" %.2f s |", c.*field);
      }
    }
  };
  std::printf("\n| items in the site | |");
  for (const Column& c : columns) std::printf(" %zu |", c.items);
  row("building the site (every run ingested)", "", &Column::build_s);
  row("ingest of the next run", "2 s", &Column::ingest_s);
  row("heatmap", "10 s", &Column::heatmap_s);
  row("report", "10 s", &Column::report_s);
  std::printf("\n");
  if (!keep) fs::remove_all(dir);
  return 0;
}

// Several processes ingest into one site at once, on both engines: nothing is lost and no item
// is stored twice (the result equals one process ingesting the runs in order), and an ingest
// killed at any moment leaves the site valid, its run absent or complete, for a rerun to finish.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <random>
#include <thread>
#include <tuple>

#include "db/site_database.hpp"
#include "heatmap/heatmap_files.hpp"
#include "site/run_ingest.hpp"
#include "support/site_engines.hpp"
#include "support/temp_dir.hpp"

namespace littermap::site {
namespace {

using littermap::test::SiteEngine;
using littermap::test::TempDir;
using littermap::test::TestSite;

constexpr int kRuns = 40;
constexpr int kSharedItems = 30;

// Run k drives along y = 10 and sees every shared item j with (j + k) % 3 == 0, where it lies
// (litter stays put), and two items no other run sees; all items are over 0.75 m apart (the
// same-item radius).
RunInput OverlappingRun(int k) {
  RunInput run;
  run.name = "run " + std::to_string(k);
  run.source_digest = "digest-" + std::to_string(k);
  run.start_time_s = 1.7e9 + 86400.0 * k;
  run.end_time_s = run.start_time_s + 600;
  for (int i = 0; i <= 600; ++i) run.T_site_base.push_back({0.1 * i, 10.0, 0.0});
  for (int j = 0; j < kSharedItems; ++j) {
    if ((j + k) % 3 != 0) continue;
    run.items.push_back(
        {"s" + std::to_string(j), j % 2 ? "can" : "bottle", {2.0 * j, 10.5}, 0.02, 0.1, 0.9});
  }
  run.items.push_back({"u1", "cup", {k + 0.5, 9.3}, 0.0, 0.1, 0.8});
  run.items.push_back({"u2", "carton", {k + 0.5, 11.7}, 0.0, 0.2, 0.7});
  return run;
}

db::SiteOptions Options() {
  db::SiteOptions options;
  options.name = "concurrent";
  options.epsg_code = 32633;
  options.origin_easting_m = 500000;
  options.origin_northing_m = 5000000;
  return options;
}

// Everything a site holds that does not depend on which process got which id first: runs by
// name, items by place, detections by run and item id, hotspots.
struct SiteContent {
  std::vector<std::string> runs;
  std::vector<std::tuple<std::string, double, double, double, double, double, int, std::string,
                         std::string>>
      items;
  std::vector<std::tuple<std::string, std::string, std::string, double, double, double, double>>
      detections;
  std::vector<std::tuple<std::int64_t, double, double, double, std::string, std::string>> hotspots;

  bool operator==(const SiteContent&) const = default;
};

SiteContent Content(db::SiteDatabase& site) {
  SiteContent content;
  std::map<std::int64_t, std::string> run_names;
  std::vector<std::int64_t> run_ids;
  for (const db::RunRecord& run : site.Runs()) {
    run_names[run.run_id] = run.name;
    run_ids.push_back(run.run_id);
    content.runs.push_back(run.name);
  }
  std::map<std::int64_t, db::PointXY> item_places;
  for (const db::ItemRecord& item : site.Items()) {
    item_places[item.fid] = item.site_xy;
    content.items.emplace_back(item.class_name, item.site_xy.x, item.site_xy.y, item.z_m,
                               item.size_m, item.confidence, item.times_seen,
                               run_names[item.first_run_id], run_names[item.last_run_id]);
  }
  for (const db::DetectionRecord& d : site.Detections(run_ids)) {
    const db::PointXY item = d.item_fid ? item_places.at(*d.item_fid) : db::PointXY{-1, -1};
    content.detections.emplace_back(run_names[d.run_id], d.run_item_id, d.class_name, d.site_xy.x,
                                    d.site_xy.y, item.x, item.y);
  }
  const auto hotspots = site.sql().Prepare(
      "SELECT rank, site_x_m, site_y_m, density_per_100m2, dominant_class, filter_class "
      "FROM hotspots");
  while (hotspots->Step()) {
    content.hotspots.emplace_back(hotspots->ColumnInt64(0), hotspots->ColumnDouble(1),
                                  hotspots->ColumnDouble(2), hotspots->ColumnDouble(3),
                                  hotspots->ColumnText(4), hotspots->ColumnText(5));
  }
  std::sort(content.runs.begin(), content.runs.end());
  std::sort(content.items.begin(), content.items.end());
  std::sort(content.detections.begin(), content.detections.end());
  std::sort(content.hotspots.begin(), content.hotspots.end());
  return content;
}

void ComputeHotspots(db::SiteDatabase& site, const std::filesystem::path& dir) {
  heatmap::HeatmapFilesOptions options;
  options.hotspots.min_items = 2;
  heatmap::WriteHeatmapFiles(site, dir, options);
}

// Runs `body` in a child process; returns its pid. The child exits 0 when body returns, 1 when
// it throws (its message on stderr).
template <typename Body>
pid_t Spawn(Body body) {
  const pid_t pid = fork();
  if (pid == 0) {
    int code = 0;
    try {
      body();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "child %d: %s\n", getpid(), e.what());
      code = 1;
    }
    std::fflush(stderr);
    _exit(code);
  }
  return pid;
}

int Wait(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

class ConcurrentIngestTest : public ::testing::TestWithParam<SiteEngine> {
 protected:
  SiteContent Sequential() {
    TestSite where(GetParam(), dir_.path(), "sequential");
    db::SiteDatabase site = db::SiteDatabase::Create(where.locator(), Options());
    for (int k = 0; k < kRuns; ++k) IngestRun(site, OverlappingRun(k), {});
    ComputeHotspots(site, dir_ / "sequential-maps");
    return Content(site);
  }

  TempDir dir_;
};

INSTANTIATE_TEST_SUITE_P(Engines, ConcurrentIngestTest,
                         ::testing::Values(SiteEngine::kGeoPackage, SiteEngine::kPostgis),
                         littermap::test::SiteEngineName);

// PostGIS: 8 processes of 5 runs each; a GeoPackage: 2 processes of 20 (SQLite has one writer at
// a time and a busy timeout, not a server). Each process also ingests another's first run again,
// which must change nothing. 20 repetitions, as a race shows only sometimes.
TEST_P(ConcurrentIngestTest, ProcessesAtOnceGiveTheSequentialResult) {
  const SiteContent expected = Sequential();
  ASSERT_EQ(expected.runs.size(), static_cast<std::size_t>(kRuns));
  ASSERT_EQ(expected.items.size(), static_cast<std::size_t>(kSharedItems + 2 * kRuns));
  ASSERT_FALSE(expected.hotspots.empty());
  const int processes = GetParam() == SiteEngine::kPostgis ? 8 : 2;
  const int per_process = kRuns / processes;
  for (int repetition = 0; repetition < 20; ++repetition) {
    TestSite where(GetParam(), dir_.path(), "at_once_" + std::to_string(repetition));
    db::SiteDatabase::Create(where.locator(), Options());
    std::vector<pid_t> children;
    for (int p = 0; p < processes; ++p) {
      children.push_back(Spawn([&, p] {
        db::SiteDatabase site = db::SiteDatabase::Open(where.locator());
        for (int k = p * per_process; k < (p + 1) * per_process; ++k) {
          IngestRun(site, OverlappingRun(k), {});
        }
        IngestRun(site, OverlappingRun(((p + 1) % processes) * per_process), {});
      }));
    }
    for (pid_t child : children) ASSERT_EQ(Wait(child), 0) << "repetition " << repetition;
    db::SiteDatabase site = db::SiteDatabase::Open(where.locator());
    ComputeHotspots(site, dir_ / ("maps-" + std::to_string(repetition)));
    const SiteContent content = Content(site);
    ASSERT_EQ(content.runs, expected.runs) << "repetition " << repetition;
    ASSERT_EQ(content.items, expected.items) << "repetition " << repetition;
    ASSERT_EQ(content.detections, expected.detections) << "repetition " << repetition;
    ASSERT_EQ(content.hotspots, expected.hotspots) << "repetition " << repetition;
  }
}

// A run large enough that its ingest takes a while, to be killed in the middle of.
RunInput LargeRun() {
  RunInput run = OverlappingRun(0);
  run.name = "large";
  run.source_digest = "digest-large";
  run.items.clear();
  for (int i = 0; i < 1500; ++i) {
    run.items.push_back(
        {std::to_string(i), "can", {(i % 50) * 1.2, 30.0 + (i / 50) * 1.2}, 0.0, 0.1, 0.9});
  }
  return run;
}

// The run is absent, or complete: its track, coverage and every detection.
void ExpectAbsentOrComplete(db::SiteDatabase& site, const RunInput& run, const std::string& when) {
  const std::optional<std::int64_t> id = site.FindRun(run.source_digest);
  if (!id) {
    EXPECT_TRUE(site.Items().empty()) << when;
    return;
  }
  EXPECT_EQ(site.DetectionCount(*id), run.items.size()) << when;
  EXPECT_EQ(site.Items().size(), run.items.size()) << when;
  EXPECT_EQ(site.RunTracks().size(), 1u) << when;
  EXPECT_EQ(site.Coverages().size(), 1u) << when;
}

TEST_P(ConcurrentIngestTest, AnIngestKilledAtAnyMomentLeavesTheSiteValid) {
  const RunInput run = LargeRun();
  // How long one ingest takes here, so the kills spread over all of it.
  double duration_s = 0.0;
  {
    TestSite where(GetParam(), dir_.path(), "timed");
    db::SiteDatabase site = db::SiteDatabase::Create(where.locator(), Options());
    const auto start = std::chrono::steady_clock::now();
    IngestRun(site, run, {});
    duration_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // Ten kills that land before the ingest ends: a moment after it (a loaded machine is slower
  // or faster than when timed) does not count, and the moments shrink.
  std::mt19937 random(7);
  int kills = 0, attempts = 0;
  for (; kills < 10 && attempts < 40; ++attempts) {
    const std::string when = "attempt " + std::to_string(attempts);
    TestSite where(GetParam(), dir_.path(), "killed_" + std::to_string(attempts));
    db::SiteDatabase::Create(where.locator(), Options());
    const pid_t child = Spawn([&] {
      db::SiteDatabase site = db::SiteDatabase::Open(where.locator());
      IngestRun(site, run, {});
    });
    std::this_thread::sleep_for(std::chrono::duration<double>(
        std::uniform_real_distribution<double>(0.0, duration_s)(random)));
    kill(child, SIGKILL);
    if (Wait(child) == 128 + SIGKILL) {
      ++kills;
    } else {
      duration_s *= 0.8;
    }
    db::SiteDatabase site = db::SiteDatabase::Open(where.locator());
    if (GetParam() == SiteEngine::kGeoPackage) {
      const auto check = site.sql().Prepare("PRAGMA integrity_check");
      ASSERT_TRUE(check->Step());
      EXPECT_EQ(check->ColumnText(0), "ok") << when;
      const auto keys = site.sql().Prepare("PRAGMA foreign_key_check");
      EXPECT_FALSE(keys->Step()) << when;
    }
    ExpectAbsentOrComplete(site, run, when);
    IngestRun(site, run, {});  // the rerun completes it
    ExpectAbsentOrComplete(site, run, when + ", rerun");
    EXPECT_TRUE(site.FindRun(run.source_digest)) << when;
  }
  EXPECT_EQ(kills, 10) << "in " << attempts << " attempts; the ingest took " << duration_s << " s";
}

}  // namespace
}  // namespace littermap::site

#pragma once
// A small site whose report is known by construction. Three weekly runs drive east along y = 0
// from x = 0, ingested out of order (week 2 first):
//   week 1, 20 m: finds A bottle (5, 0), B can (10, 0), C cup (15, 0)
//   week 2, 20 m: finds A, C and D bottle (13, 0); B is gone
//   week 3,  6 m: finds A and E cup (3, 0); its camera reaches x ~ 10, short of C and D
// Week 1 comes with a reconstruct quality.json (20 of 110 scans by odometry, one warning).

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "site/run_ingest.hpp"

namespace littermap::reports {

constexpr double kFixtureStart_s = 1793524800.0;  // 2026-11-01 09:20 UTC

inline std::vector<PlanarPose> EastwardTrack(double length_m) {
  std::vector<PlanarPose> poses;
  for (int i = 0; i <= static_cast<int>(std::lround(length_m / 0.1)); ++i) {
    poses.push_back({0.1 * i, 0.0, 0.0});
  }
  return poses;
}

inline site::RunInput FixtureRun(int week, double length_m,
                                 const std::vector<site::RunItem>& items) {
  site::RunInput run;
  run.name = "week " + std::to_string(week);
  run.source_digest = "fixture-week-" + std::to_string(week);
  run.start_time_s = kFixtureStart_s + (week - 1) * 7 * 86400.0;
  run.end_time_s = run.start_time_s + 600;
  run.T_site_base = EastwardTrack(length_m);
  run.items = items;
  return run;
}

inline db::SiteDatabase CreateFixtureSite(const std::filesystem::path& file,
                                          const std::string& name) {
  db::SiteOptions options;
  options.name = name;
  db::SiteDatabase site = db::SiteDatabase::Create(file, options);
  const site::RunItem a{"a", "bottle", {5, 0}, 0, 0.2, 0.9};
  const site::RunItem b{"b", "can", {10, 0}, 0, 0.1, 0.9};
  const site::RunItem c{"c", "cup", {15, 0}, 0, 0.1, 0.9};
  const site::RunItem d{"d", "bottle", {13, 0}, 0, 0.2, 0.9};
  const site::RunItem e{"e", "cup", {3, 0}, 0, 0.1, 0.9};
  site::RunItem a_again = a;
  a_again.xy = {5.1, 0.05};
  site::RunInput week1 = FixtureRun(1, 20, {a, b, c});
  week1.reconstruction_quality =
      R"({"scans": 110, "routines": {"global": 90, "buffer": 0, "rgbd": 0, "odometry-only": 20},
          "key_frames": 12, "loop_closures_found": 3, "loop_closures_accepted": 2,
          "warnings": ["3 scans had too few valid ranges and were placed by odometry"]})";
  const site::IngestOptions ingest;
  site::IngestRun(site, FixtureRun(2, 20, {a_again, c, d}), ingest);
  site::IngestRun(site, week1, ingest);
  site::IngestRun(site, FixtureRun(3, 6, {a, e}), ingest);
  return site;
}

}  // namespace littermap::reports

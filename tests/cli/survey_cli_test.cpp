// littermap survey and report end to end on the simulator: three weekly runs of one park (the
// litter changing between them) into one site, one report whose figures match the database and
// which headless Chromium renders without errors or network requests; and a survey that
// resumes, redoes on --force, and names the stage that failed.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/sqlite_database.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;
using test::TempDir;

// A short simulated run (the first metres of the sample park's loop) on a given week.
void Simulate(const std::filesystem::path& dir, int week, double duration_s) {
  char start[32];
  std::snprintf(start, sizeof start, "2026-11-%02dT09:00", 1 + 7 * week);
  const auto result =
      RunLittermap("-q simulate " + Quote(test::SampleWorld()) + " -o " + Quote(dir / "bag") +
                   " --truth " + Quote(dir / "truth") + " --duration " +
                   std::to_string(duration_s) + " --run-seed " + std::to_string(week + 1) +
                   " --litter-day " + std::to_string(week) + " --start-time " + start);
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::int64_t Integer(SqliteDatabase& database, const std::string& sql, std::int64_t run_id = 0) {
  SqliteStatement query = database.Prepare(sql);
  if (sql.find('?') != std::string::npos) query.Bind(1, run_id);
  return query.Step() ? query.ColumnInt64(0) : -1;
}

double Real(SqliteDatabase& database, const std::string& sql, std::int64_t run_id) {
  SqliteStatement query = database.Prepare(sql);
  query.Bind(1, run_id);
  return query.Step() ? query.ColumnDouble(0) : -1;
}

TEST(SurveyCli, ThreeWeeklyRunsMakeOneReportThatMatchesTheDatabase) {
  TempDir dir;
  const auto site_file = dir / "park.gpkg";
  for (int week = 0; week < 3; ++week) {
    const auto week_dir = dir / ("week" + std::to_string(week + 1));
    Simulate(week_dir, week, 40.0);
    const auto survey =
        RunLittermap("survey " + Quote(week_dir / "bag") + " --site " + Quote(site_file) + " -o " +
                     Quote(week_dir / "out") + " --name week" + std::to_string(week + 1) +
                     // 40-second runs find one or two items per place
                     " --every 4 --hotspot-min-items 1");
    ASSERT_EQ(survey.exit_code, 0) << survey.output;
    for (const char* stage : {"[1/5 reconstruct]", "[2/5 detect]", "[3/5 ingest]", "[4/5 heatmap]",
                              "[5/5 report]", "Report: "}) {
      EXPECT_NE(survey.output.find(stage), std::string::npos) << stage << "\n" << survey.output;
    }
  }
  const auto report_dir = dir / "week3" / "out" / "report";
  const nlohmann::json report = ReadJson(report_dir / "report.json");

  // Every figure of the report, recounted from the database with SQL.
  SqliteDatabase db(site_file, SqliteDatabase::Mode::kReadOnly);
  EXPECT_EQ(report["totals"]["runs"], Integer(db, "SELECT count(*) FROM runs"));
  ASSERT_EQ(report["runs"].size(), 3u);
  EXPECT_EQ(report["totals"]["items"],
            Integer(db, "SELECT count(DISTINCT item_fid) FROM detections"));
  EXPECT_EQ(report["totals"]["detections"], Integer(db, "SELECT count(*) FROM detections"));
  {
    SqliteStatement classes = db.Prepare(
        "SELECT class, count(*) FROM litter_items WHERE fid IN (SELECT item_fid FROM detections) "
        "GROUP BY class");
    std::map<std::string, int> expected;
    while (classes.Step())
      expected[classes.ColumnText(0)] = static_cast<int>(classes.ColumnInt64(1));
    EXPECT_EQ(report["items_by_class"].get<decltype(expected)>(), expected);
  }
  int new_items = 0;
  for (const auto& run : report["runs"]) {
    const std::int64_t id = run["run_id"];
    EXPECT_EQ(run["items_found"],
              Integer(db, "SELECT count(DISTINCT item_fid) FROM detections WHERE run_id = ?", id));
    EXPECT_EQ(run["detections"],
              Integer(db, "SELECT count(*) FROM detections WHERE run_id = ?", id));
    // New: items whose first detection (by run start time) is this run's.
    EXPECT_EQ(run["new_items"],
              Integer(db,
                      "SELECT count(*) FROM (SELECT item_fid, min(r.start_time_s) AS first "
                      "FROM detections JOIN runs r USING (run_id) GROUP BY item_fid) "
                      "WHERE first = (SELECT start_time_s FROM runs WHERE run_id = ?)",
                      id));
    EXPECT_EQ(run["items_found"].get<int>(),
              run["new_items"].get<int>() + run["items_still_there"].get<int>());
    EXPECT_NEAR(run["length_m"].get<double>(),
                Real(db, "SELECT length_m FROM runs WHERE run_id = ?", id), 1e-9);
    EXPECT_NEAR(run["observed_area_m2"].get<double>(),
                Real(db, "SELECT observed_area_m2 FROM coverage WHERE run_id = ?", id), 1e-9);
    EXPECT_TRUE(run["reconstruction"]["known"].get<bool>());
    EXPECT_GT(run["length_m"].get<double>(), 15.0);  // 40 s at 0.6 m/s
    EXPECT_GE(run["items_found"].get<int>(), 1);     // litter lines the first leg's path
    new_items += run["new_items"].get<int>();
  }
  EXPECT_EQ(new_items, report["totals"]["items"].get<int>());
  // The report's hotspots are the heatmap's, stored in the site.
  ASSERT_FALSE(report["hotspots"].empty());
  for (const auto& hotspot : report["hotspots"]) {
    SqliteStatement stored = db.Prepare(
        "SELECT site_x_m, site_y_m, density_per_100m2, dominant_class FROM hotspots WHERE "
        "rank = ? AND filter_class = ''");
    stored.Bind(1, hotspot["rank"].get<std::int64_t>());
    ASSERT_TRUE(stored.Step()) << hotspot["rank"];
    EXPECT_NEAR(hotspot["site_x_m"].get<double>(), stored.ColumnDouble(0), 1e-6);
    EXPECT_NEAR(hotspot["site_y_m"].get<double>(), stored.ColumnDouble(1), 1e-6);
    EXPECT_NEAR(hotspot["density_per_100m2"].get<double>(), stored.ColumnDouble(2), 1e-3);
    EXPECT_EQ(hotspot["dominant_class"], stored.ColumnText(3));
    EXPECT_EQ(hotspot["density_by_run"].size(), 3u);
  }

  // `littermap report` for a period gives the same figures for the runs in it.
  const auto period = RunLittermap("report " + Quote(site_file) + " -o " + Quote(dir / "weeks23") +
                                   " --from 2026-11-05");
  ASSERT_EQ(period.exit_code, 0) << period.output;
  const nlohmann::json weeks23 = ReadJson(dir / "weeks23" / "report.json");
  ASSERT_EQ(weeks23["runs"].size(), 2u);
  EXPECT_EQ(weeks23["runs"][0]["new_items"], report["runs"][1]["new_items"]);
  EXPECT_EQ(weeks23["runs"][1]["items_gone"], report["runs"][2]["items_gone"]);

  // What a reader gets: headless Chromium opens the page, with screenshots kept for people.
  const std::filesystem::path screenshots =
      std::filesystem::path(LITTERMAP_TEST_OUTPUT_DIR) / "survey-report";
  const std::string check =
      "python3 " + Quote(std::filesystem::path(LITTERMAP_SOURCE_DIR) / "scripts/check-report.py") +
      " " + Quote(report_dir) + " --screenshots " + Quote(screenshots) + " 2>&1";
  FILE* pipe = popen(check.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  EXPECT_EQ(pclose(pipe), 0) << output;
  EXPECT_NE(output.find("0 network requests"), std::string::npos) << output;
  EXPECT_TRUE(std::filesystem::exists(screenshots / "desktop.png"));
  std::printf("report screenshots: %s\n", screenshots.c_str());
}

TEST(SurveyCli, ResumesRedoesOnForceAndNamesTheFailingStage) {
  TempDir dir;
  Simulate(dir / "run", 0, 15.0);
  const std::string survey = "survey " + Quote(dir / "run" / "bag") + " --site " +
                             Quote(dir / "park.gpkg") + " --every 5 -o ";
  const auto first = RunLittermap(survey + Quote(dir / "out"));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("Created site 'park'"), std::string::npos) << first.output;

  const auto again = RunLittermap(survey + Quote(dir / "out"));
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("[1/5 reconstruct] up to date"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("[2/5 detect] up to date"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("already in"), std::string::npos) << again.output;

  // A stage cut short (no completion mark) is redone, and the later ones after it.
  std::filesystem::remove(dir / "out" / ".stages" / "detect.done");
  const auto resumed = RunLittermap(survey + Quote(dir / "out"));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("[1/5 reconstruct] up to date"), std::string::npos);
  EXPECT_NE(resumed.output.find("[2/5 detect]\n"), std::string::npos) << resumed.output;

  // --force redoes everything; the same inputs give the same results, so the site is unchanged.
  const auto forced = RunLittermap(survey + Quote(dir / "out") + " --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_EQ(forced.output.find("up to date"), std::string::npos) << forced.output;
  EXPECT_NE(forced.output.find("already in"), std::string::npos) << forced.output;

  // A broken model fails the detect stage; the reconstruction before it stays.
  std::ofstream(dir / "broken.yml") << "not a model\n";
  const auto failed = RunLittermap(survey + Quote(dir / "out2") + " --name other --model " +
                                   Quote(dir / "broken.yml"));
  EXPECT_EQ(failed.exit_code, 2) << failed.output;
  EXPECT_NE(failed.output.find("survey stage 'detect' failed"), std::string::npos) << failed.output;
  EXPECT_NE(failed.output.find("broken.yml"), std::string::npos) << failed.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "out2" / "run" / "trajectory.tum"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out2" / ".stages" / "reconstruct.done"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out2" / ".stages" / "detect.done"));
}

}  // namespace
}  // namespace littermap

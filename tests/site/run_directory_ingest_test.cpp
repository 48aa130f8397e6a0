// A run directory into a site by its file name: what ingesting says, and a run name that the
// site already holds with other results.

#include "site/run_directory_ingest.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::site {
namespace {

using littermap::test::TempDir;

// A run along y = 2 from x = 0 to x = 20 (10 Hz at 0.5 m/s), with `items` cans beside the path.
void WriteRun(const std::filesystem::path& dir, int items, const char* items_file = "items.csv") {
  std::filesystem::create_directories(dir);
  std::ofstream tum(dir / "trajectory.tum");
  for (int i = 0; i <= 400; ++i) {
    char line[128];
    std::snprintf(line, sizeof line, "%.3f %.3f 2 0 0 0 0 1\n", 1.7e9 + 0.1 * i, 0.05 * i);
    tum << line;
  }
  std::ofstream csv(dir / items_file);
  csv << "id,class,x,y,z,size_m\n";
  for (int i = 1; i <= items; ++i) csv << i << ",can," << 4 * i << ",3,0,0.1\n";
}

class RunDirectoryIngestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    db::SiteOptions options;
    options.name = "park";
    db::SiteDatabase::Create(site_, options);
  }
  TempDir dir_;
  std::filesystem::path site_ = dir_ / "park.gpkg";
};

TEST_F(RunDirectoryIngestTest, SaysWhatItAddedAndThatAgainChangesNothing) {
  WriteRun(dir_ / "week1", 3);
  RunDirectoryIngestOptions options;
  options.name = "week 1";
  const RunDirectoryIngestResult first = IngestRunDirectory(site_, dir_ / "week1", options);
  char counts[160];
  std::snprintf(counts, sizeof counts,
                "Ingested run 1 'week 1': 401 poses, 20.0 m driven, %.0f m2 observed, 3 "
                "detections (3 new items, 0 seen again)",
                first.ingest.observed_area_m2);
  EXPECT_EQ(IngestSummary(first, site_),
            (dir_ / "week1").string() +
                ": no map.yaml to match; the run is placed where it starts (the dock, the site "
                "origin)\n" +
                counts);
  const RunDirectoryIngestResult again = IngestRunDirectory(site_, dir_ / "week1", options);
  EXPECT_TRUE(again.notes.empty());
  EXPECT_EQ(IngestSummary(again, "park.gpkg"),
            "Run week 1 is already in park.gpkg as run 1; nothing changed");
}

TEST_F(RunDirectoryIngestTest, RefusesOtherResultsUnderANameInUse) {
  WriteRun(dir_ / "a" / "run", 3);
  WriteRun(dir_ / "b" / "run", 2);
  RunDirectoryIngestOptions options;
  options.name = "week 1";
  IngestRunDirectory(site_, dir_ / "a" / "run", options);
  EXPECT_TRUE(IngestRunDirectory(site_, dir_ / "a" / "run", options).ingest.already_ingested);
  try {
    IngestRunDirectory(site_, dir_ / "b" / "run", options);
    ADD_FAILURE() << "other results under a name in use were ingested";
  } catch (const BadInputError& e) {
    EXPECT_EQ(std::string(e.what()),
              site_.string() +
                  ": already holds a run named 'week 1' with other results (run 1); the site "
                  "keeps it. To add these results as another run, give --name");
  }
  options.name = "week 2";
  EXPECT_EQ(IngestRunDirectory(site_, dir_ / "b" / "run", options).ingest.run_id, 2);
  // Named from their folders, two runs in folders called "run" are not both "run".
  WriteRun(dir_ / "week3" / "run", 1);
  WriteRun(dir_ / "week4-survey" / "run", 4);
  EXPECT_EQ(IngestRunDirectory(site_, dir_ / "week3" / "run/", {}).name, "week3");
  EXPECT_EQ(IngestRunDirectory(site_, dir_ / "week4-survey" / "run", {}).name, "week4");
  options.name = std::string("week \xff");
  EXPECT_THROW(IngestRunDirectory(site_, dir_ / "b" / "run", options), BadInputError);
}

TEST_F(RunDirectoryIngestTest, OneOfAThingIsSingular) {
  WriteRun(dir_ / "one", 1);
  const std::string summary = IngestSummary(IngestRunDirectory(site_, dir_ / "one", {}), site_);
  EXPECT_NE(summary.find(" 1 detection (1 new item, 0 seen again)"), std::string::npos) << summary;
}

TEST_F(RunDirectoryIngestTest, CountsTheTruthItemsOutsideTheCameraCoverage) {
  WriteRun(dir_ / "truth", 2, "litter.csv");
  std::ofstream(dir_ / "truth" / "litter.csv", std::ios::app) << "3,can,10,40,0,0.1\n";
  const RunDirectoryIngestResult result = IngestRunDirectory(site_, dir_ / "truth", {});
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("no items.csv; using the simulator's truth"),
            std::string::npos);
  const std::string summary = IngestSummary(result, site_);
  EXPECT_NE(summary.find("'truth': 401 poses"), std::string::npos) << summary;
  EXPECT_NE(summary.find("(2 new items, 0 seen again, 1 outside the camera coverage skipped)"),
            std::string::npos)
      << summary;
}

}  // namespace
}  // namespace littermap::site

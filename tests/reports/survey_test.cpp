// The survey's stages on a run directory whose reconstruct and detect stages finished before:
// skipped while up to date, the site created, ingest refusing other results under the run's
// name, and a failing stage named with where its earlier outputs are.

#include "reports/survey.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reports {
namespace {

namespace fs = std::filesystem;
using littermap::test::TempDir;

// A 20 m x 10 m walled map (0.1 m cells) and a run along y = 2 with three cans beside it.
void WriteRunDirectory(const fs::path& run, double start_time_s = 1.7e9) {
  fs::create_directories(run);
  std::ofstream(run / "map.yaml") << "image: map.pgm\nresolution: 0.1\norigin: [-1.0, -1.0, 0.0]\n"
                                     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const int width = 220, height = 120;
  std::ofstream pgm(run / "map.pgm", std::ios::binary);
  pgm << "P5\n" << width << " " << height << "\n255\n";
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const bool wall = row < 5 || row >= height - 5 || col < 5 || col >= width - 5 ||
                        (col % 40 == 0 && row > 60);
      pgm.put(static_cast<char>(wall ? 0 : 254));
    }
  }
  std::ofstream tum(run / "trajectory.tum");
  for (int i = 0; i <= 300; ++i) {
    char line[96];
    std::snprintf(line, sizeof line, "%.3f %.3f 2 0 0 0 0 1\n", start_time_s + 0.1 * i, 0.05 * i);
    tum << line;
  }
  std::ofstream(run / "items.csv") << "id,class,x,y,z,size_m\n1,can,3,3,0,0.1\n"
                                      "2,can,7,3,0,0.1\n3,bottle,11,1,0,0.1\n";
  std::ofstream(run / "detections.csv") << "frame\n";
  std::ofstream(run / "quality.json") << "{\"scans\": 301, \"warnings\": [\"a test run\"]}\n";
}

// Every file under `dir` an hour old.
void Age(const fs::path& dir) {
  const auto hour_ago = fs::file_time_type::clock::now() - std::chrono::hours(1);
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) fs::last_write_time(entry.path(), hour_ago);
  }
}

class SurveyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "bag");
    std::ofstream(dir_ / "bag" / "bag_0.db3") << "not a bag";
    std::ofstream(dir_ / "model.yml") << "not a model";
    options_.bag = dir_ / "bag";
    options_.site = dir_ / "park.gpkg";
    options_.output_dir = dir_ / "out";
    options_.name = "week1";
    options_.detect.model = dir_ / "model.yml";
    callbacks_.print = [this](const std::string& text) { printed_.push_back(text); };
    callbacks_.warn = [this](const std::string& text) { warned_.push_back(text); };
  }

  // The run directory as reconstruct and detect left it, with their stages marked finished.
  void FinishEarlierStages() {
    WriteRunDirectory(dir_ / "out" / "run");
    Age(dir_.path());
    std::ofstream(dir_ / "out" / ".stages" / "reconstruct.done") << "reconstruct finished\n";
    std::ofstream(dir_ / "out" / ".stages" / "detect.done") << "detect finished\n";
  }

  TempDir dir_;
  SurveyOptions options_;
  SurveyCallbacks callbacks_;
  std::vector<std::string> printed_;
  std::vector<std::string> warned_;
};

TEST_F(SurveyTest, SkipsTheStagesUpToDateAndRunsTheOthers) {
  fs::create_directories(dir_ / "out" / ".stages");
  FinishEarlierStages();
  const SurveyResult result = RunSurvey(options_, callbacks_);
  ASSERT_EQ(printed_.size(), 9u);
  EXPECT_EQ(printed_[0], "Created site 'park' in " + options_.site.display +
                             ": local frame, positions in metres from the dock (for GPS "
                             "coordinates create the site first with 'littermap site init "
                             "--crs')");
  EXPECT_EQ(printed_[1],
            "[1/5 reconstruct] up to date (outputs newer than inputs), skipped; --force redoes it");
  EXPECT_EQ(printed_[2],
            "[2/5 detect] up to date (outputs newer than inputs), skipped; --force redoes it");
  EXPECT_EQ(printed_[3], "[3/5 ingest]");
  EXPECT_EQ(printed_[4].rfind("The run's map becomes the site map\nIngested run 1 'week1': 301 "
                              "poses, 15.0 m driven, ",
                              0),
            0u)
      << printed_[4];
  EXPECT_EQ(printed_[5], "[4/5 heatmap]");
  EXPECT_EQ(printed_[6].rfind("1 run, 3 items (3 detections), ", 0), 0u) << printed_[6];
  EXPECT_EQ(printed_[7], "[5/5 report]");
  EXPECT_EQ(printed_[8],
            "wrote " + (dir_ / "out" / "report" / "index.html").string() + " and report.json");
  ASSERT_EQ(warned_.size(), 1u);
  EXPECT_NE(warned_[0].find("not georeferenced"), std::string::npos) << warned_[0];

  EXPECT_EQ(result.name, "week1");
  EXPECT_EQ(result.report_html, dir_ / "out" / "report" / "index.html");
  EXPECT_TRUE(fs::exists(result.report_html));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "maps" / "density.tif"));
  ASSERT_EQ(result.report.runs.size(), 1u);
  EXPECT_EQ(result.report.runs[0].quality.scans, 301);  // quality.json, read back from the site
  for (const char* stage : {"reconstruct", "detect", "ingest", "heatmap", "report"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / ".stages" / (std::string(stage) + ".done"))) << stage;
  }

  // Again: the same results are in the site already.
  printed_.clear();
  RunSurvey(options_, callbacks_);
  ASSERT_EQ(printed_.size(), 8u);
  EXPECT_EQ(printed_[3],
            "Run week1 is already in " + options_.site.display + " as run 1; nothing changed");

  // Other results under the same name: the site keeps the ones it has.
  std::ofstream(dir_ / "out" / "run" / "items.csv", std::ios::app) << "4,can,15,3,0,0.1\n";
  Age(dir_ / "out" / "run");
  try {
    RunSurvey(options_, callbacks_);
    ADD_FAILURE() << "other results under the name week1 were ingested";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput);
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("survey stage 'ingest' failed: " + options_.site.display +
                                ": already holds a run named 'week1' with other results (run 1)",
                            0),
              0u)
        << message;
    EXPECT_NE(
        message.find("\n  the earlier stages' outputs are kept in " + (dir_ / "out").string() +
                     "; once fixed, the same command resumes at this stage"),
        std::string::npos)
        << message;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / ".stages" / "ingest.done"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / ".stages" / "detect.done"));
}

TEST_F(SurveyTest, NamesTheStageThatFailed) {
  try {
    RunSurvey(options_, callbacks_);
    ADD_FAILURE() << "a file that is no bag was reconstructed";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("survey stage 'reconstruct' failed: ", 0), 0u)
        << e.what();
  }
  ASSERT_EQ(printed_.size(), 2u);
  EXPECT_EQ(printed_[1], "[1/5 reconstruct]");
  EXPECT_TRUE(fs::exists(options_.site.file));
  EXPECT_TRUE(fs::is_directory(dir_ / "out" / ".stages"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / ".stages" / "reconstruct.done"));
}

TEST_F(SurveyTest, WantsABagDirectory) {
  options_.bag = dir_ / "model.yml";
  try {
    RunSurvey(options_, callbacks_);
    ADD_FAILURE() << "a file was taken for a bag directory";
  } catch (const BadInputError& e) {
    EXPECT_EQ(std::string(e.what()), options_.bag.string() + ": not a run bag directory");
  }
  EXPECT_TRUE(printed_.empty());
  EXPECT_FALSE(fs::exists(options_.site.file));
}

// Three runs given out of time order, two at a time: the site takes them in the order they
// started, every line names its run, and a run that fails leaves the others finished.
TEST_F(SurveyTest, SeveralRunsReachTheSiteInTheOrderTheyStarted) {
  const std::vector<std::pair<std::string, double>> weeks = {
      {"week3", 1.7e9 + 2 * 604800.0}, {"week1", 1.7e9}, {"week2", 1.7e9 + 604800.0}};
  std::vector<SurveyOptions> runs;
  for (const auto& [name, start] : weeks) {
    SurveyOptions run = options_;
    run.name = name;
    run.bag = dir_ / name / "bag";
    run.output_dir = dir_ / "out" / name;
    fs::create_directories(run.bag);
    fs::create_directories(run.output_dir / ".stages");
    WriteRunDirectory(run.output_dir / "run", start);
    runs.push_back(run);
  }
  Age(dir_.path());
  for (const SurveyOptions& run : runs) {
    std::ofstream(run.output_dir / ".stages" / "reconstruct.done") << "reconstruct finished\n";
    std::ofstream(run.output_dir / ".stages" / "detect.done") << "detect finished\n";
  }
  const std::vector<SurveyResult> results = RunSurveys(runs, 2, callbacks_);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].name, "week1");
  EXPECT_EQ(results[1].name, "week2");
  EXPECT_EQ(results[2].name, "week3");
  ASSERT_EQ(results[2].report.runs.size(), 3u);  // the last report sees the whole site
  std::vector<std::string> ingested;
  for (const std::string& line : printed_) {
    EXPECT_EQ(line.front(), '[') << line;
    if (line.find("] Ingested run ") != std::string::npos ||
        line.find("\nIngested run ") != std::string::npos) {
      ingested.push_back(line.substr(0, line.find(']') + 1));
    }
  }
  EXPECT_EQ(ingested, (std::vector<std::string>{"[week1]", "[week2]", "[week3]"}));

  // A fourth run whose items cannot be read: the others are done, the error names it.
  SurveyOptions broken = options_;
  broken.name = "week4";
  broken.bag = dir_ / "week4" / "bag";
  broken.output_dir = dir_ / "out" / "week4";
  fs::create_directories(broken.bag);
  fs::create_directories(broken.output_dir / ".stages");
  WriteRunDirectory(broken.output_dir / "run", 1.7e9 + 3 * 604800.0);
  std::ofstream(broken.output_dir / "run" / "items.csv") << "id,class\n1\n";
  Age(broken.output_dir);
  std::ofstream(broken.output_dir / ".stages" / "reconstruct.done") << "reconstruct finished\n";
  std::ofstream(broken.output_dir / ".stages" / "detect.done") << "detect finished\n";
  runs.push_back(broken);
  try {
    RunSurveys(runs, 2, callbacks_);
    FAIL() << "a broken run passed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput);
    EXPECT_EQ(
        std::string(e.what()).rfind("1 of 4 runs failed (the others finished):\nweek4: survey "
                                    "stage 'ingest' failed: ",
                                    0),
        0u)
        << e.what();
  }
  EXPECT_THROW(RunSurveys(runs, 0, callbacks_), UsageError);
  runs[1].name = "week3";
  EXPECT_THROW(RunSurveys(runs, 2, callbacks_), UsageError);  // two runs named week3
}

}  // namespace
}  // namespace littermap::reports

// `littermap detect`, `samples`, `train` and `eval segmentation` end to end on the first 45 s of
// the sample park (seed 7, not a training seed of the shipped model): three litter items come
// within the depth camera's range and view on the way, among natural look-alikes.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

using test::Quote;

// Items scored against the truth of the 45 s: three litter items in view, at least two found (one
// may be missed at --every 2), at most one false alarm among the look-alikes, most natural items
// recognised as natural.
void ExpectTheLitterFound(const std::filesystem::path& items, const std::filesystem::path& truth) {
  const auto eval =
      RunLittermap("eval detections " + Quote(items) + " " + Quote(truth / "litter.csv") +
                   " --natural " + Quote(truth / "natural.csv") + " --visible " +
                   Quote(truth / "masks" / "visible.csv") + " --json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto json = nlohmann::json::parse(eval.output);
  EXPECT_EQ(json.at("truth_litter").get<int>(), 3) << items << ": " << eval.output;
  EXPECT_GE(json.at("true_positives").get<int>(), 2) << items << ": " << eval.output;
  EXPECT_LE(json.at("false_positives").get<int>(), 1) << items << ": " << eval.output;
  EXPECT_GE(json.at("litter_natural_accuracy").get<double>(), 0.75) << items << ": " << eval.output;
}

// One simulation for all checks: ctest runs every test in its own process.
TEST(DetectCli, EndToEndOnTheFirst45SecondsOfTheSamplePark) {
  test::TempDir d;
  const auto world =
      std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_small.yaml";
  auto result = RunLittermap("simulate " + Quote(world) + " -o " + Quote(d / "bag") + " --truth " +
                             Quote(d / "truth") + " --duration 45 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::filesystem::create_directories(d / "run");

  // detect with the shipped model, scored against the truth.
  result =
      RunLittermap("detect " + Quote(d / "bag") + " --run " + Quote(d / "run") + " --trajectory " +
                   Quote(d / "truth" / "trajectory.tum") + " --every 2 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("225 frames"), std::string::npos) << result.output;
  std::ifstream items(d / "run" / "items.csv");
  std::string header;
  std::getline(items, header);
  EXPECT_EQ(header,
            "id,class,x,y,z,size_m,confidence,views,missed_views,litter,litter_probability,"
            "first_seen_ns,last_seen_ns");
  // Every item kept was seen in at least three quarters of the frames that could see it.
  for (std::string line; std::getline(items, line);) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 13u) << line;
    const int views = std::stoi(fields[7]), missed = std::stoi(fields[8]);
    EXPECT_GE(views, 3 * missed) << line;
  }
  ExpectTheLitterFound(d / "run" / "items.csv", d / "truth");

  // Segmentation IoU on the instance masks: objects with 100+ depth pixels are mostly cut out,
  // by the defaults (the geometry at half resolution) and by the full-resolution profile.
  const auto full = std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "detect_full.yaml";
  for (const std::string& options : {std::string(), " --options " + Quote(full)}) {
    result = RunLittermap("eval segmentation " + Quote(d / "bag") + " " + Quote(d / "truth") +
                          options + " --json --quiet");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const auto iou = nlohmann::json::parse(result.output);
    ASSERT_TRUE(iou.contains("all")) << result.output;
    EXPECT_GE(iou["all"]["objects"].get<int>(), 5);
    EXPECT_GE(iou["all"]["mean_iou"].get<double>(), 0.5) << options << ": " << result.output;
  }

  // The full-resolution profile finds the same items within the same tolerances.
  result =
      RunLittermap("detect " + Quote(d / "bag") + " --run " + Quote(d / "run") + " -o " +
                   Quote(d / "full") + " --trajectory " + Quote(d / "truth" / "trajectory.tum") +
                   " --options " + Quote(full) + " --every 2 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ExpectTheLitterFound(d / "full" / "items.csv", d / "truth");

  // samples + train make a model detect can use.
  result = RunLittermap("samples " + Quote(d / "bag") + " --truth " + Quote(d / "truth") + " -o " +
                        Quote(d / "samples") + " --every 3 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // Samples cut with detect's options file: the full-resolution segmentation, as the shipped
  // model's were.
  result =
      RunLittermap("samples " + Quote(d / "bag") + " --truth " + Quote(d / "truth") + " -o " +
                   Quote(d / "samples_full") + " --options " + Quote(full) + " --every 9 --quiet");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find(" samples ("), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(d / "samples_full" / "labels.csv"));
  result = RunLittermap("train " + Quote(d / "samples") + " -o " + Quote(d / "model.yml.gz") +
                        " --trees 20 --validate " + Quote(d / "samples"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("combined (random forest)"), std::string::npos) << result.output;
  result =
      RunLittermap("detect " + Quote(d / "bag") + " --run " + Quote(d / "run") + " -o " +
                   Quote(d / "own") + " --trajectory " + Quote(d / "truth" / "trajectory.tum") +
                   " --model " + Quote(d / "model.yml.gz") + " --every 5 --quiet");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(std::filesystem::exists(d / "own" / "detections.csv"));
}

TEST(DetectCli, BadInputNamesTheFile) {
  test::TempDir d;
  std::filesystem::create_directories(d / "bag");
  std::filesystem::create_directories(d / "run");
  std::ofstream(d / "truth_trajectory.tum") << "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n";
  std::ofstream(d / "bad_model.yml") << "%YAML:1.0\nformat: nonsense\n";
  auto result =
      RunLittermap("detect " + Quote(d / "bag") + " --run " + Quote(d / "run") + " --trajectory " +
                   Quote(d / "truth_trajectory.tum") + " --model " + Quote(d / "bad_model.yml"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("bad_model.yml"), std::string::npos) << result.output;
  // A run directory without a trajectory: the message names the missing file.
  std::filesystem::create_directories(d / "run_no_traj");
  result = RunLittermap("detect " + Quote(d / "bag") + " --run " + Quote(d / "run_no_traj"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("trajectory.tum"), std::string::npos) << result.output;
  // samples reads detect's options file and names a bad key.
  std::filesystem::create_directories(d / "truth");
  std::ofstream(d / "bad_options.yaml") << "geometry_step_px: 9\n";
  result = RunLittermap("samples " + Quote(d / "bag") + " --truth " + Quote(d / "truth") + " -o " +
                        Quote(d / "samples") + " --options " + Quote(d / "bad_options.yaml"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("bad_options.yaml"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("geometry_step_px"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace littermap

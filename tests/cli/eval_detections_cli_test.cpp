// littermap eval detections: the --json keys and figures of a small scene, the text tables, and
// the exit codes of bad files (2) and bad arguments (1).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::RunLittermap;
using test::TempDir;

// Truth: cans 1 and 2, a bottle 3 the camera barely saw, a leaf 4 and a stone 5. Detected: can
// 1 right, can 2 called a cup, the leaf called a cup (a false positive), the stone as natural,
// and a bag where there is nothing.
void WriteScene(const TempDir& dir) {
  std::ofstream(dir / "litter.csv") << "id,class,x,y,z,size_m\n"
                                       "1,can,0.0,0.0,0.03,0.12\n"
                                       "2,can,5.0,0.0,0.03,0.12\n"
                                       "3,bottle,10.0,0.0,0.04,0.25\n";
  std::ofstream(dir / "natural.csv") << "id,class,x,y,z,size_m\n"
                                        "4,leaf,15.0,0.0,0.01,0.08\n"
                                        "5,stone,20.0,0.0,0.05,0.10\n";
  std::ofstream(dir / "visible.csv") << "frame,object_id,pixels\n"
                                        "0,1,800\n1,2,90\n2,2,400\n2,3,12\n3,4,150\n3,5,700\n";
  std::ofstream(dir / "items.csv") << "id,class,x,y,z,size_m,confidence\n"
                                      "a,can,0.1,0.0,0.03,0.12,0.9\n"
                                      "b,cup,5.0,-0.2,0.03,0.12,0.8\n"
                                      "c,cup,15.0,0.1,0.01,0.08,0.6\n"
                                      "d,stone,20.0,0.0,0.05,0.10,0.7\n"
                                      "e,plastic_bag,30.0,0.0,0.01,0.30,0.5\n";
}

std::string Arguments(const TempDir& dir) {
  return "eval detections " + (dir / "items.csv").string() + " " + (dir / "litter.csv").string() +
         " --natural " + (dir / "natural.csv").string() + " --visible " +
         (dir / "visible.csv").string();
}

TEST(EvalDetectionsCli, JsonHasStableKeysAndRightFigures) {
  TempDir dir;
  WriteScene(dir);
  const auto result = RunLittermap(Arguments(dir) + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  for (const char* key :
       {"precision", "recall", "f1", "true_positives", "false_positives", "false_negatives",
        "class_accuracy", "litter_natural_accuracy", "litter_natural_pairs", "truth_litter",
        "detected_litter", "below_confidence", "per_class", "recall_by_masks", "confusion",
        "match_radius_m", "min_confidence"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  // Bottle 3 (12 pixels) is left out. Litter: a and b match cans 1 and 2; c and e are false.
  EXPECT_EQ(json.at("truth_litter"), 2);
  EXPECT_EQ(json.at("detected_litter"), 4);
  EXPECT_EQ(json.at("true_positives"), 2);
  EXPECT_EQ(json.at("false_positives"), 2);
  EXPECT_EQ(json.at("false_negatives"), 0);
  // Exact fractions of small integers; 1e-12 covers the division's rounding.
  EXPECT_NEAR(json.at("precision").get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(json.at("recall").get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(json.at("f1").get<double>(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(json.at("class_accuracy").get<double>(), 0.5, 1e-12);
  EXPECT_EQ(json.at("litter_natural_pairs"), 4);  // a-1, b-2, c-4, d-5
  EXPECT_NEAR(json.at("litter_natural_accuracy").get<double>(), 0.75, 1e-12);
  EXPECT_DOUBLE_EQ(json.at("match_radius_m").get<double>(), 0.3);
  const auto& can = json.at("per_class").at("can");
  EXPECT_EQ(can.at("truth"), 2);
  EXPECT_EQ(can.at("detected"), 1);
  EXPECT_EQ(can.at("tp"), 1);
  EXPECT_NEAR(can.at("precision").get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(can.at("recall").get<double>(), 0.5, 1e-12);
  EXPECT_EQ(json.at("per_class").size(), 7u);  // the seven litter classes
  // Both cans were seen in one mask with 100 pixels or more (can 2's other has 90).
  const auto& by_masks = json.at("recall_by_masks");
  EXPECT_EQ(by_masks.at("1").at("truth"), 2);
  EXPECT_EQ(by_masks.at("1").at("tp"), 2);
  EXPECT_EQ(by_masks.at("2").at("truth"), 0);
  EXPECT_EQ(by_masks.at("3+").at("truth"), 0);
  const auto& confusion = json.at("confusion");
  EXPECT_EQ(confusion.at("can").at("can"), 1);
  EXPECT_EQ(confusion.at("can").at("cup"), 1);
  EXPECT_EQ(confusion.at("natural").at("cup"), 1);
  EXPECT_EQ(confusion.at("natural").at("natural"), 1);
  EXPECT_EQ(confusion.at("none").at("plastic_bag"), 1);
  EXPECT_EQ(confusion.at("bottle").at("none"), 0);  // left out by the visibility filter
}

TEST(EvalDetectionsCli, MinPixelsRadiusAndConfidenceChangeTheAnswer) {
  TempDir dir;
  WriteScene(dir);
  const auto all = RunLittermap(Arguments(dir) + " --min-pixels 10 --json");
  ASSERT_EQ(all.exit_code, 0) << all.output;
  const auto all_json = nlohmann::json::parse(all.output);
  EXPECT_EQ(all_json.at("false_negatives"), 1);  // bottle 3 counts
  // At 10 pixels can 2 was seen in two masks, and the missed bottle in one.
  EXPECT_EQ(all_json.at("recall_by_masks").at("1").at("truth"), 2);
  EXPECT_EQ(all_json.at("recall_by_masks").at("1").at("tp"), 1);
  EXPECT_EQ(all_json.at("recall_by_masks").at("2").at("truth"), 1);
  EXPECT_EQ(all_json.at("recall_by_masks").at("2").at("tp"), 1);
  const auto tight = RunLittermap(Arguments(dir) + " --match-radius 0.15 --json");
  ASSERT_EQ(tight.exit_code, 0) << tight.output;
  EXPECT_EQ(nlohmann::json::parse(tight.output).at("true_positives"), 1);  // b is 0.2 m off
  // c (0.6, the leaf taken for a cup) and e (0.5, the bag at nothing) are less sure than 0.65.
  const auto sure = RunLittermap(Arguments(dir) + " --min-confidence 0.65 --json");
  ASSERT_EQ(sure.exit_code, 0) << sure.output;
  const auto sure_json = nlohmann::json::parse(sure.output);
  EXPECT_EQ(sure_json.at("below_confidence"), 2);
  EXPECT_EQ(sure_json.at("false_positives"), 0);
  EXPECT_EQ(sure_json.at("true_positives"), 2);
}

TEST(EvalDetectionsCli, TextShowsTheTables) {
  TempDir dir;
  WriteScene(dir);
  const auto result = RunLittermap(Arguments(dir));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* text : {"precision          0.500", "recall             1.000", "food_container",
                           "confusion (rows: truth, columns: predicted)"}) {
    EXPECT_NE(result.output.find(text), std::string::npos) << text << "\n" << result.output;
  }
}

TEST(EvalDetectionsCli, BadFilesExitTwoAndNameFileAndColumn) {
  TempDir dir;
  WriteScene(dir);
  std::ofstream(dir / "items.csv") << "id,class,y\na,can,0\n";
  const auto missing_column = RunLittermap(Arguments(dir));
  EXPECT_EQ(missing_column.exit_code, 2) << missing_column.output;
  EXPECT_NE(
      missing_column.output.find((dir / "items.csv").string() + ":1: the header has no column 'x'"),
      std::string::npos)
      << missing_column.output;

  std::ofstream(dir / "items.csv") << "id,class,x,y\na,can,0,zero\n";
  const auto bad_number = RunLittermap(Arguments(dir));
  EXPECT_EQ(bad_number.exit_code, 2) << bad_number.output;
  EXPECT_NE(bad_number.output.find("items.csv:2: column 'y'"), std::string::npos)
      << bad_number.output;

  const auto no_file = RunLittermap("eval detections " + (dir / "nothing.csv").string() + " " +
                                    (dir / "litter.csv").string());
  EXPECT_EQ(no_file.exit_code, 2) << no_file.output;
  EXPECT_NE(no_file.output.find("nothing.csv"), std::string::npos) << no_file.output;
}

TEST(EvalDetectionsCli, BadArgumentsExitOne) {
  TempDir dir;
  WriteScene(dir);
  const std::string files = (dir / "items.csv").string() + " " + (dir / "litter.csv").string();
  EXPECT_EQ(RunLittermap("eval detections " + files + " --min-pixels 10").exit_code, 1);
  EXPECT_EQ(RunLittermap("eval detections " + files + " --match-radius 0").exit_code, 1);
  EXPECT_EQ(RunLittermap("eval detections " + files + " --min-confidence 1.5").exit_code, 1);
  EXPECT_EQ(RunLittermap("eval detections " + (dir / "items.csv").string()).exit_code, 1);
}

// A run reconstructed in its own map frame: the frame is the truth's world turned by 90 degrees
// and shifted by (4, 4). --align carries the items back with the trajectories' alignment.
TEST(EvalDetectionsCli, AlignCarriesItemsOfARunIntoTheTruthFrame) {
  TempDir dir;
  WriteScene(dir);
  // Truth frame point (x, y) is run frame (y - 4, 4 - x): rotation by -90 degrees, then shift.
  std::ofstream run_items(dir / "run_items.csv");
  run_items << "id,class,x,y\n";
  for (const auto& [id, cls, x, y] :
       std::vector<std::tuple<const char*, const char*, double, double>>{{"a", "can", 0.0, 0.0},
                                                                         {"b", "can", 5.0, 0.0}}) {
    run_items << id << ',' << cls << ',' << y - 4 << ',' << 4 - x << '\n';
  }
  run_items.close();
  std::ofstream reference(dir / "reference.tum"), estimate(dir / "estimate.tum");
  for (int i = 0; i < 20; ++i) {  // an L-shaped drive, so the alignment is well determined
    const double x = i < 10 ? i : 9, y = i < 10 ? 0 : i - 9;
    reference << i << " " << x << " " << y << " 0 0 0 0 1\n";
    estimate << i << " " << y - 4 << " " << 4 - x << " 0 0 0 -0.7071068 0.7071068\n";
  }
  reference.close();
  estimate.close();
  const std::string common = "eval detections " + (dir / "run_items.csv").string() + " " +
                             (dir / "litter.csv").string() + " --json";
  auto result = RunLittermap(common);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(nlohmann::json::parse(result.output).at("true_positives"), 0);
  result = RunLittermap(common + " --align " + (dir / "estimate.tum").string() + " " +
                        (dir / "reference.tum").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(nlohmann::json::parse(result.output).at("true_positives"), 2) << result.output;
}

}  // namespace
}  // namespace littermap

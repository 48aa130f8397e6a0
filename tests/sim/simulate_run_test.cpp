// A simulated run with its outputs: the bag, the ground truth with its occupancy map and the
// contact sheet, each reported when written; a bad duration writes nothing.

#include "sim/simulate_run.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "sim/sim_test_support.hpp"
#include "sim/truth_map.hpp"
#include "support/temp_dir.hpp"

namespace littermap::sim {
namespace {

TEST(SimulateRun, WritesAndReportsTheBagTheTruthAndTheContactSheetInTurn) {
  test::TempDir dir;
  SimulateRunOptions options;
  options.record.seed = 3;
  options.duration_s = 2.0;
  options.truth_dir = dir / "truth";
  options.contact_sheet_png = dir / "sheet.png";
  std::vector<std::string> lines;
  const SimulateRunResult result =
      SimulateRun(LoadWorldSpec(test::SampleWorld()), dir / "bag", options, {},
                  [&lines, &dir](const std::string& line) {
                    lines.push_back(line);
                    // Each output is complete when it is reported.
                    const char* written[] = {"bag", "truth/map.pgm", "sheet.png"};
                    EXPECT_TRUE(std::filesystem::exists(dir / written[lines.size() - 1])) << line;
                  });
  EXPECT_EQ(result.record.scans, 21u);  // 10 Hz over 0..2 s
  EXPECT_FALSE(result.record.route_completed);
  ASSERT_TRUE(result.contact_sheet);
  ASSERT_EQ(lines.size(), 3u);
  const std::string bag_line = "wrote " + (dir / "bag").string() +
                               ": 21 scans (urg-04lx), 101 odometry, 101 imu, 20 rgb-d frames, "
                               "2.0 s, ";
  EXPECT_EQ(lines[0].substr(0, bag_line.size()), bag_line);
  EXPECT_NE(lines[0].find(" m (route cut short) (seed 3, run seed 3, "), std::string::npos)
      << lines[0];
  EXPECT_EQ(lines[1], "wrote " + (dir / "truth").string() + ": " +
                          std::to_string(result.record.litter) + " litter, " +
                          std::to_string(result.record.natural) + " natural look-alikes, " +
                          std::to_string(result.record.objects) + " primitives, 2 masks, map.pgm");
  EXPECT_EQ(lines[2], "wrote " + (dir / "sheet.png").string() +
                          ": 6 frames (colour | depth | "
                          "laser), " +
                          std::to_string(result.contact_sheet->width_px) + "x" +
                          std::to_string(result.contact_sheet->height_px) + " px");
  EXPECT_TRUE(std::filesystem::exists(dir / "truth" / "map.yaml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sheet.png"));
}

TEST(SimulateRun, NamesTheRouteDrivenAndWritesOnlyWhatIsAsked) {
  test::TempDir dir;
  SimulateRunOptions options;
  options.record.route = "route";
  options.duration_s = 0.5;
  std::vector<std::string> lines;
  SimulateRun(LoadWorldSpec(test::SampleWorld()), dir / "bag", options, {},
              [&lines](const std::string& line) { lines.push_back(line); });
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find(", route route, "), std::string::npos) << lines[0];
}

TEST(SimulateRun, ADurationThatIsNotPositiveIsAUsageErrorAndWritesNothing) {
  test::TempDir dir;
  SimulateRunOptions options;
  options.truth_dir = dir / "truth";
  for (const double duration_s : {0.0, -1.0, std::nan("")}) {
    options.duration_s = duration_s;
    EXPECT_THROW(SimulateRun(LoadWorldSpec(test::SampleWorld()), dir / "bag", options), UsageError);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  EXPECT_FALSE(std::filesystem::exists(dir / "truth"));
}

TEST(TruthMap, DrawsTheScansAtTheTruePoses) {
  test::TempDir dir;
  const Simulation simulation(LoadWorldSpec(test::SampleWorld()), {2.0});
  WriteTruthMap(simulation, dir.path());
  const cv::Mat map = cv::imread((dir / "map.pgm").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(map.empty());
  ASSERT_TRUE(std::filesystem::exists(dir / "map.yaml"));
  // The grid covers the park (40 m x 30 m and a metre around it) at 5 cm cells.
  const WorldSpec& spec = simulation.world().spec;
  EXPECT_GE(map.cols * 0.05, spec.size_x_m + 2 - 0.1);
  EXPECT_GE(map.rows * 0.05, spec.size_y_m + 2 - 0.1);
  EXPECT_GT(cv::countNonZero(map == 0), 10) << "occupied cells where the laser hit";
  EXPECT_GT(cv::countNonZero(map == 254), 1000) << "free cells along the beams";
}

}  // namespace
}  // namespace littermap::sim

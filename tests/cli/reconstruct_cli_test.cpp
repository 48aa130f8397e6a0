// `littermap reconstruct` and `littermap eval trajectory` end to end on a real CARMEN log
// (orebro, 237 scans): the run directory's files, the JSON keys, and the exit codes.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "support/carmen_import.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

using test::Quote;

using test::Slurp;

TEST(ReconstructCli, OrebroRunDirectoryAndEvaluation) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::ImportCarmen("orebro", 2, dir.path()));
  const auto run =
      RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "run"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("237 poses"), std::string::npos) << run.output;
  for (const char* file : {"trajectory.tum", "keyframes.tum", "odometry.tum", "map.pgm", "map.yaml",
                           "map.png", "routines.csv", "loops.csv", "quality.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "run" / file)) << file;
  }
  const auto quality = nlohmann::json::parse(Slurp(dir / "run" / "quality.json"));
  EXPECT_EQ(quality["scans"], 237);
  for (const char* key : {"routines", "loop_closures_found", "loop_closures_accepted",
                          "loop_closures_rejected", "final_cost", "run_time_s"}) {
    EXPECT_TRUE(quality.contains(key)) << key;
  }
  const std::string routines = Slurp(dir / "run" / "routines.csv");
  EXPECT_EQ(routines.rfind("time,routine,matching_ratio,landmark_sightings\n", 0), 0u);
  EXPECT_EQ(std::count(routines.begin(), routines.end(), '\n'), 238);

  const auto eval = RunLittermap("eval trajectory " + Quote(dir / "run" / "trajectory.tum") + " " +
                                 Quote(dir / "ref.tum") + " --json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto metrics = nlohmann::json::parse(eval.output);
  // A functional check of the command chain on a short log (measured 0.11-0.26 m ATE, 0.03 m
  // RPE on seed 2); the accuracy targets are asserted on ACES in reconstruct_tests and reported
  // for every log by bench/slam_carmen.sh.
  EXPECT_LE(metrics["ate_rmse_m"].get<double>(), 0.3);
  EXPECT_LE(metrics["rpe_trans_mean_m"].get<double>(), 0.05);
  EXPECT_TRUE(metrics.contains("rpe_rot_mean_deg"));
}

TEST(ReconstructCli, BadInputExitCodes) {
  test::TempDir dir;
  {
    std::ofstream tum(dir / "a.tum");
    tum << "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n3.0 2 0 0 0 0 0 1\n";
    std::ofstream other(dir / "b.tum");
    other << "100.0 0 0 0 0 0 0 1\n101.0 1 0 0 0 0 0 1\n102.0 2 0 0 0 0 0 1\n";
  }
  // No common time: bad input (2), and the message says so.
  const auto disjoint =
      RunLittermap("eval trajectory " + Quote(dir / "a.tum") + " " + Quote(dir / "b.tum"));
  EXPECT_EQ(disjoint.exit_code, 2) << disjoint.output;
  EXPECT_NE(disjoint.output.find("associate"), std::string::npos) << disjoint.output;
  // A directory that is not a bag.
  std::filesystem::create_directories(dir / "empty");
  EXPECT_EQ(RunLittermap("-q reconstruct " + Quote(dir / "empty") + " -o " + Quote(dir / "run"))
                .exit_code,
            2);
  EXPECT_EQ(RunLittermap("reconstruct").exit_code, 1);
  EXPECT_EQ(RunLittermap("eval trajectory " + Quote(dir / "a.tum")).exit_code, 1);
}

// A simulated run with a camera: the RGB-D routine's files, one camera pose per frame tracked,
// and the same run without it (--no-rgbd) writes none of them.
TEST(ReconstructCli, SimulatedRunWithACameraWritesTheCameraTrack) {
  test::TempDir dir;
  const auto world =
      std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_small.yaml";
  ASSERT_EQ(RunLittermap("-q simulate " + Quote(world) + " -o " + Quote(dir / "bag") + " --truth " +
                         Quote(dir / "truth") + " --duration 8")
                .exit_code,
            0);
  const auto run =
      RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "run"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto quality = nlohmann::json::parse(Slurp(dir / "run" / "quality.json"));
  EXPECT_EQ(quality["rgbd"]["frames"], 80);  // 8 s at 10 Hz
  // The robot drives 0.6 m/s on flat ground: an RGB-D key frame every 15 cm or so.
  EXPECT_GE(quality["rgbd"]["key_frames"].get<int>(), 20);
  const std::string track = Slurp(dir / "run" / "camera.tum");
  EXPECT_EQ(std::count(track.begin(), track.end(), '\n'), 1 + 80)
      << track.substr(0, 200);  // header
  const std::string sources = Slurp(dir / "run" / "camera_sources.csv");
  EXPECT_EQ(sources.substr(0, sources.find('\n')), "time,source");
  EXPECT_NE(sources.find(",laser\n"), std::string::npos);

  const auto laser = RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " +
                                  Quote(dir / "laser") + " --no-rgbd");
  ASSERT_EQ(laser.exit_code, 0) << laser.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "laser" / "camera.tum"));
  EXPECT_FALSE(nlohmann::json::parse(Slurp(dir / "laser" / "quality.json")).contains("rgbd"));
}

}  // namespace
}  // namespace littermap

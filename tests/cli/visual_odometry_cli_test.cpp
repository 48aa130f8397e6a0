// `littermap import tum` + `reconstruct` + `eval trajectory` on a TUM RGB-D format sequence
// without laser: visual odometry alone. The sequence is the park simulator's camera along the
// first 20 s of the sample park's route (15 Hz, freiburg3 intrinsics, groundtruth.txt of the
// optical frame), so the score is against exact ground truth.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/sim_tum_sequence.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;

TEST(VisualOdometryCli, TumSequenceWithoutLaserIsTrackedByTheCameraAndScored) {
  test::TempDir d;
  const auto sequence = d / "rgbd_dataset_freiburg3_sim_park";
  const std::size_t frames = test::WriteSimTumSequence(
      std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_small.yaml",
      sequence);
  ASSERT_EQ(frames, 301u);
  auto result = RunLittermap("-q import tum " + Quote(sequence) + " -o " + Quote(d / "bag") +
                             " --reference " + Quote(d / "reference.tum"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  result = RunLittermap("reconstruct " + Quote(d / "bag") + " -o " + Quote(d / "run"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("visual odometry"), std::string::npos) << result.output;

  std::ifstream in(d / "run" / "quality.json");
  const auto quality = nlohmann::json::parse(in);
  EXPECT_EQ(quality["mode"], "visual-odometry");
  EXPECT_EQ(quality["frames"], 301);
  // Measured: every frame tracked in one segment, 98 key frames.
  EXPECT_GE(quality["frames_tracked"].get<int>(), 290);
  EXPECT_EQ(quality["segments"], 1);
  const auto eval = RunLittermap("eval trajectory " + Quote(d / "run" / "trajectory.tum") + " " +
                                 Quote(d / "reference.tum") + " --json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto metrics = nlohmann::json::parse(eval.output);
  // 12 m of park lawn and trees: measured ATE 0.022 m.
  EXPECT_LT(metrics["ate_rmse_m"].get<double>(), 0.1);
  EXPECT_LT(metrics["rpe_trans_mean_m"].get<double>(), 0.03);
  EXPECT_GE(metrics["associated_poses"].get<int>(), 290);
}

}  // namespace
}  // namespace littermap

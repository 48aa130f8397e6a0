// A trajectory file settled on a bag of the known room: the true poses hardly move and noisy
// ones move by about their noise; the settled poses are written; what is left out is warned of;
// the output's directory is checked before anything is read; the JSON keys and the text.

#include "reconstruct/trajectory_settling.hpp"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "reconstruct/room_bag.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

TEST(TrajectorySettling, TruePosesHardlyMoveNoisyOnesSettle) {
  test::TempDir dir;
  const test::RoomScans run = test::RoomRun();
  test::WriteRoomBag(dir / "bag", run);
  bag::WriteTumTrajectory(dir / "truth.tum", run.truth);
  bag::WriteTumTrajectory(dir / "noisy.tum", test::Perturbed(run.truth, 0.05, 1 * test::kDeg));

  TrajectorySettlingOptions options;
  options.output = dir / "settled.tum";
  std::vector<std::string> steps, warnings;
  const TrajectorySettling truth = SettleTrajectory(
      dir / "bag", dir / "truth.tum", options,
      [&](const Progress& p) { steps.push_back(std::string(p.task)); },
      [&](const std::string& warning) { warnings.push_back(warning); });
  EXPECT_EQ(steps, (std::vector<std::string>{
                       "reading the scans of " + (dir / "bag").string(),
                       "aligning the scans from the poses of " + (dir / "truth.tum").string()}));
  EXPECT_TRUE(warnings.empty());
  // As scan_settling_test.cpp measures it: 34 scans a frame spacing apart, a sub-millimetre move.
  EXPECT_EQ(truth.settling.settled.size(), 34u);
  EXPECT_LT(truth.moved.ate_rmse_m, 0.001);
  EXPECT_EQ(bag::ReadTumTrajectory(dir / "settled.tum").size(), 34u);

  const TrajectorySettling noisy = SettleTrajectory(dir / "bag", dir / "noisy.tum", {});
  EXPECT_GT(noisy.moved.ate_rmse_m, 0.02);
  EXPECT_LT(noisy.moved.ate_rmse_m, 0.2);

  const auto json = nlohmann::ordered_json::parse(ToJson(truth));
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"scans", "scans_posed", "scans_placed", "scans_aligned",
                                            "scan_pairs", "point_pairs", "usable", "ate_rmse_m",
                                            "ate_max_m", "rpe_trans_mean_m", "rpe_rot_mean_deg"}));
  EXPECT_EQ(json["scans_aligned"], 34);
  const std::string text = ToText(truth, {});
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "scans aligned      34 of 100 (one per 0.50 m or 17 deg of motion)");
  EXPECT_NE(text.find("\nmoved to agree with its scans:\nATE RMSE           0.000"),
            std::string::npos)
      << text;
  EXPECT_NE(text.back(), '\n');
}

TEST(TrajectorySettling, WarnsOfScansWithoutAPose) {
  test::TempDir dir;
  const test::RoomScans run = test::RoomRun();
  test::WriteRoomBag(dir / "bag", run);
  const std::vector<StampedPose> half(run.truth.begin(), run.truth.begin() + 50);
  bag::WriteTumTrajectory(dir / "half.tum", half);
  std::vector<std::string> warnings;
  const TrajectorySettling settled =
      SettleTrajectory(dir / "bag", dir / "half.tum", {}, {},
                       [&](const std::string& warning) { warnings.push_back(warning); });
  EXPECT_EQ(settled.settling.scans_posed, 50u);
  EXPECT_EQ(warnings, std::vector<std::string>{"50 of 100 scans have no pose in " +
                                               (dir / "half.tum").string() +
                                               " close enough in time, and are left out"});
}

TEST(TrajectorySettling, Refusals) {
  test::TempDir dir;
  test::WriteRoomBag(dir / "bag", test::RoomRun());
  std::ofstream(dir / "other.tum") << "5.0 0 0 0 0 0 0 1\n6.0 1 0 0 0 0 0 1\n";
  test::ExpectBadInput([&] { SettleTrajectory(dir / "bag", dir / "other.tum", {}); },
                       (dir / "other.tum").string() + ": scan settling:");
  TrajectorySettlingOptions options;
  options.output = dir / "missing" / "settled.tum";
  try {
    // Checked before the bag is read: this one does not exist.
    SettleTrajectory(dir / "no_bag", dir / "other.tum", options);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& error) {
    EXPECT_EQ(std::string(error.what()),
              options.output.string() + ": its directory does not exist");
  }
  options.output.clear();
  options.max_time_difference_s = -1;
  EXPECT_THROW(SettleTrajectory(dir / "bag", dir / "other.tum", options), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct

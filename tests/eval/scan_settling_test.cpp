// Settling a trajectory on its scans in a known room: the true poses stay where they are, noisy
// poses settle onto the truth and the move measures their error; thinning, left-out scans and
// the refusals.

#include "eval/scan_settling.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "room_run.hpp"

namespace littermap::eval {
namespace {

std::vector<StampedPose> ToStamped(const std::vector<std::pair<TimestampNs, PlanarPose>>& poses) {
  std::vector<StampedPose> stamped;
  for (const auto& [stamp_ns, pose] : poses) stamped.push_back(Stamped(stamp_ns, pose));
  return stamped;
}

double AteM(const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& reference) {
  return EvaluateTrajectory(estimate, reference, {}).ate_rmse_m;
}

TEST(ScanSettling, TruePosesStayWhereTheyAre) {
  const RoomScans run = RoomRun();
  const ScanSettling settling = SettleOnScans(run.scans, kBaseLaser, run.truth);
  EXPECT_EQ(settling.scans, 100u);
  EXPECT_EQ(settling.scans_placed, 100u);
  // Consecutive poses are 2 pi 3 m / 100 = 0.19 m and 3.6 deg apart: every third scan is the
  // first to lie 0.5 m from the last one kept, so scans 0, 3, ..., 99 are aligned.
  ASSERT_EQ(settling.settled.size(), 34u);
  EXPECT_EQ(settling.settled[1].first, run.scans[3].stamp_ns);
  EXPECT_TRUE(settling.alignment.usable);
  EXPECT_GT(settling.alignment.pairs_matched, 33u);
  const double moved_m = AteM(ToStamped(settling.given), ToStamped(settling.settled));
  RecordProperty("true_poses_moved_m", std::to_string(moved_m));
  EXPECT_LT(moved_m, 0.002);
}

TEST(ScanSettling, NoisyPosesSettleOntoTheTruth) {
  const RoomScans run = RoomRun();
  // Pose errors of a good SLAM result's size, and twice that.
  for (const double sigma_m : {0.02, 0.04}) {
    const std::vector<StampedPose> noisy = Perturbed(run.truth, sigma_m, sigma_m * 25 * kDeg);
    const ScanSettling settling = SettleOnScans(run.scans, kBaseLaser, noisy);
    const std::vector<StampedPose> given = ToStamped(settling.given);
    const std::vector<StampedPose> settled = ToStamped(settling.settled);
    const double error_m = AteM(given, run.truth);
    const double settled_error_m = AteM(settled, run.truth);
    const double moved_m = AteM(given, settled);
    RecordProperty("sigma_" + std::to_string(sigma_m) + "_error_settled_moved_m",
                   std::to_string(error_m) + " " + std::to_string(settled_error_m) + " " +
                       std::to_string(moved_m));
    // The scans see all four walls: they pin every pose down to a few millimetres, so the move
    // is the noise itself.
    EXPECT_LT(settled_error_m, 0.2 * error_m) << "sigma " << sigma_m;
    EXPECT_NEAR(moved_m, error_m, 0.2 * error_m) << "sigma " << sigma_m;
  }
}

TEST(ScanSettling, LeavesOutScansWithoutAPoseOrEchoes) {
  RoomScans run = RoomRun();
  // No echo at all in scan 1, and scan 2 far from any pose in time.
  run.scans[1].ranges_m.assign(run.scans[1].ranges_m.size(),
                               std::numeric_limits<float>::infinity());
  run.scans[2].stamp_ns += 50'000'000;  // 50 ms from its pose, 50 ms from the next
  ScanSettlingOptions every_scan;
  every_scan.frame_spacing_m = 0;
  every_scan.frame_spacing_rad = 0;
  const ScanSettling settling = SettleOnScans(run.scans, kBaseLaser, run.truth, every_scan);
  EXPECT_EQ(settling.scans, 100u);
  EXPECT_EQ(settling.scans_placed, 98u);
  EXPECT_EQ(settling.settled.size(), 98u);
  EXPECT_EQ(settling.settled[1].first, run.scans[3].stamp_ns);
}

TEST(ScanSettling, RefusesWhatCannotBeSettled) {
  const RoomScans run = RoomRun();
  EXPECT_THROW(SettleOnScans(run.scans, kBaseLaser, {}), BadInputError);
  // A trajectory of another time places no scan; one scan alone cannot be aligned.
  const std::vector<StampedPose> other = {Stamped(999'000'000'000LL, {0, 0, 0})};
  EXPECT_THROW(SettleOnScans(run.scans, kBaseLaser, other), BadInputError);
  EXPECT_THROW(SettleOnScans({run.scans[0]}, kBaseLaser, run.truth), BadInputError);
  ScanSettlingOptions bad;
  bad.hold_sigma_m = 0;
  EXPECT_THROW(SettleOnScans(run.scans, kBaseLaser, run.truth, bad), UsageError);
  bad = {};
  bad.max_time_difference_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SettleOnScans(run.scans, kBaseLaser, run.truth, bad), UsageError);
  bad = {};
  bad.alignment.max_correspondence_distances_m = {};
  EXPECT_THROW(SettleOnScans(run.scans, kBaseLaser, run.truth, bad), UsageError);
}

}  // namespace
}  // namespace littermap::eval

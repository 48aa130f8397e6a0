// Settling a trajectory on its scans in a known room: the true poses stay where they are, noisy
// poses settle onto the truth and the move measures their error; stamp order, thinning, left-out
// scans and the refusals.

#include "reconstruct/scan_settling.hpp"

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "eval/trajectory_metrics.hpp"
#include "support/room_run.hpp"

namespace littermap::reconstruct {
namespace {

using test::kBaseLaser;
using test::kDeg;
using test::Perturbed;
using test::RoomRun;
using test::RoomScans;

double AteM(const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& reference) {
  return eval::EvaluateTrajectory(estimate, reference, {}).ate_rmse_m;
}

// The trajectory's pose of every scan, as the CLI looks it up.
std::vector<std::optional<PlanarPose>> PosesOf(const RoomScans& run,
                                               const std::vector<StampedPose>& trajectory) {
  std::vector<TimestampNs> stamps_ns;
  for (const LaserScan& scan : run.scans) stamps_ns.push_back(scan.stamp_ns);
  return eval::PlanarPosesAt(trajectory, stamps_ns, 0.02);
}

TEST(ScanSettling, TruePosesStayWhereTheyAre) {
  const RoomScans run = RoomRun();
  const ScanSettling settling = SettleOnScans(run.scans, PosesOf(run, run.truth), kBaseLaser);
  EXPECT_EQ(settling.scans, 100u);
  EXPECT_EQ(settling.scans_posed, 100u);
  EXPECT_EQ(settling.scans_placed, 100u);
  // Consecutive poses are 2 pi 3 m / 100 = 0.19 m and 3.6 deg apart: every third scan is the
  // first to lie 0.5 m from the last one kept, so scans 0, 3, ..., 99 are aligned.
  ASSERT_EQ(settling.settled.size(), 34u);
  EXPECT_EQ(settling.settled[1].first, run.scans[3].stamp_ns);
  EXPECT_TRUE(settling.alignment.usable);
  EXPECT_GT(settling.alignment.pairs_matched, 33u);
  // Noise-free echoes on straight walls: the alignment's optimum is the truth, up to the
  // solver's tolerance (measured 0.2 mm); a millimetre would be a bias.
  const double moved_m =
      AteM(StampedPosesFromPlanar(settling.given), StampedPosesFromPlanar(settling.settled));
  RecordProperty("true_poses_moved_m", std::to_string(moved_m));
  EXPECT_LT(moved_m, 0.001);
}

TEST(ScanSettling, NoisyPosesSettleOntoTheTruth) {
  const RoomScans run = RoomRun();
  // Pose errors of a good SLAM result's size, and 2.5 times that.
  for (const double sigma_m : {0.02, 0.05}) {
    const std::vector<StampedPose> noisy = Perturbed(run.truth, sigma_m, sigma_m * 25 * kDeg);
    const ScanSettling settling = SettleOnScans(run.scans, PosesOf(run, noisy), kBaseLaser);
    const std::vector<StampedPose> given = StampedPosesFromPlanar(settling.given);
    const std::vector<StampedPose> settled = StampedPosesFromPlanar(settling.settled);
    const double error_m = AteM(given, run.truth);
    const double settled_error_m = AteM(settled, run.truth);
    const double moved_m = AteM(given, settled);
    RecordProperty("sigma_" + std::to_string(sigma_m) + "_error_settled_moved_m",
                   std::to_string(error_m) + " " + std::to_string(settled_error_m) + " " +
                       std::to_string(moved_m));
    // Every scan sees all four walls, which pin its pose down: the settled poses are the truth,
    // so the move is the error itself (measured within 0.1 %).
    EXPECT_LT(settled_error_m, 0.1 * error_m) << "sigma " << sigma_m;
    EXPECT_NEAR(moved_m, error_m, 0.1 * error_m) << "sigma " << sigma_m;
  }
}

TEST(ScanSettling, AlignsInStampOrderAndLeavesOutScansWithoutAPoseOrEchoes) {
  RoomScans run = RoomRun();
  // No echo at all in scan 1; scan 2 without a pose; scans 5 and 6 swapped in the input.
  run.scans[1].ranges_m.assign(run.scans[1].ranges_m.size(),
                               std::numeric_limits<float>::infinity());
  std::vector<std::optional<PlanarPose>> poses = PosesOf(run, run.truth);
  poses[2].reset();
  std::swap(run.scans[5], run.scans[6]);
  std::swap(poses[5], poses[6]);
  ScanSettlingOptions every_scan;
  every_scan.frame_spacing_m = 0;
  every_scan.frame_spacing_rad = 0;
  const ScanSettling settling = SettleOnScans(run.scans, poses, kBaseLaser, every_scan);
  EXPECT_EQ(settling.scans, 100u);
  EXPECT_EQ(settling.scans_posed, 99u);
  EXPECT_EQ(settling.scans_placed, 98u);
  ASSERT_EQ(settling.settled.size(), 98u);
  EXPECT_EQ(settling.settled[1].first, run.truth[3].stamp_ns);
  for (std::size_t k = 1; k < settling.settled.size(); ++k) {
    EXPECT_LT(settling.given[k - 1].first, settling.given[k].first);
    EXPECT_EQ(settling.settled[k].first, settling.given[k].first);
  }
  // Scan 5 (at index 6 now) is aligned with its own pose.
  EXPECT_EQ(settling.given[3].first, run.truth[5].stamp_ns);
  EXPECT_NEAR(settling.given[3].second.x_m, run.truth[5].position_m.x(), 1e-9);
}

TEST(ScanSettling, RefusesWhatCannotBeSettled) {
  const RoomScans run = RoomRun();
  const std::vector<std::optional<PlanarPose>> truth = PosesOf(run, run.truth);
  // No poses at all (a trajectory of another time), or two scans only.
  EXPECT_THROW(SettleOnScans(run.scans, std::vector<std::optional<PlanarPose>>(100), kBaseLaser),
               BadInputError);
  EXPECT_THROW(SettleOnScans({run.scans[0], run.scans[50]}, {truth[0], truth[50]}, kBaseLaser),
               BadInputError);
  // A robot standing still: every scan placed, but one frame.
  const std::vector<std::optional<PlanarPose>> still(100, truth[0]);
  EXPECT_THROW(SettleOnScans(run.scans, still, kBaseLaser), BadInputError);
  // Three scans that see no common walls: poses 100 m apart.
  EXPECT_THROW(SettleOnScans({run.scans[0], run.scans[1], run.scans[2]},
                             {PlanarPose{0, 0, 0}, PlanarPose{100, 0, 0}, PlanarPose{200, 0, 0}},
                             kBaseLaser),
               BadInputError);
  EXPECT_THROW(SettleOnScans(run.scans, std::vector<std::optional<PlanarPose>>(3), kBaseLaser),
               InternalError);
  ScanSettlingOptions bad;
  bad.hold_sigma_m = 0;
  EXPECT_THROW(SettleOnScans(run.scans, truth, kBaseLaser, bad), UsageError);
  bad = {};
  bad.frame_spacing_rad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SettleOnScans(run.scans, truth, kBaseLaser, bad), UsageError);
  bad = {};
  bad.alignment.max_correspondence_distances_m = {};
  EXPECT_THROW(SettleOnScans(run.scans, truth, kBaseLaser, bad), UsageError);
  EXPECT_THROW(eval::PlanarPosesAt(run.truth, {0}, -1), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct

// Real data: CARMEN logs from ../shared/datasets/carmen imported with seeded odometry noise
// (datasets/README.md). ICP on real consecutive scans, and the whole pipeline on ACES and the
// Intel lab against the corrected reference (each log reconstructed here once per option set;
// the CLI tests of the same logs do not reconstruct them again), and the raw CSAIL log against
// the benchmark's verified relations. A missing data set fails these tests.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "bag/tum_trajectory.hpp"
#include "eval/pose_relations.hpp"
#include "eval/trajectory_metrics.hpp"
#include "importers/carmen_importer.hpp"
#include "importers/carmen_log.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/reconstruction.hpp"
#include "reconstruct/slam_pipeline.hpp"
#include "reconstruct/trajectory_map_sharpness.hpp"
#include "support/angles.hpp"
#include "support/carmen_import.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

using test::kDeg;

PlanarPose Planar(const StampedPose& pose) {
  const Eigen::Vector3d x = pose.orientation * Eigen::Vector3d::UnitX();
  return {pose.position_m.x(), pose.position_m.y(), std::atan2(x.y(), x.x())};
}

TEST(CarmenSlam, IcpOnRealIntelScans) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(littermap::test::ImportCarmen("intel", 1, dir.path()));
  std::vector<std::string> warnings;
  const PlanarPose T_base_laser = ReadLaserExtrinsic(dir / "bag", {}, &warnings);
  const auto scans = ReadScans(dir / "bag", "/scan");
  ASSERT_EQ(scans.size(), 910u);
  const auto reference = bag::ReadTumTrajectory(dir / "ref.tum");
  IcpOptions options;
  const auto points = [&](std::size_t i) {
    return VoxelDownsample(ScanToPoints(scans[i], T_base_laser, {}).points_base, 0.05);
  };
  // 1. A real scan against itself moved by a known offset: recovered exactly.
  const PlanarPose offset{0.2, -0.1, 3 * kDeg};
  const IcpTarget self(points(20), options);
  const IcpResult moved = MatchIcp(TransformPoints(Inverse(offset), points(20)), self, {}, options);
  ASSERT_TRUE(moved.converged);
  const PlanarPose recovered = Between(offset, moved.T_target_source);  // should be identity
  EXPECT_NEAR(recovered.x_m, 0, 1e-3);
  EXPECT_NEAR(recovered.y_m, 0, 1e-3);
  EXPECT_NEAR(recovered.theta_rad, 0, 0.05 * kDeg);
  // 2. Consecutive real scans against the corrected reference, which is good to a few cm:
  // 6 cm and 1 degree (the reference's own accuracy plus ours; measured at most 4.6 cm, 0.6 deg).
  int matched = 0;
  for (std::size_t i = 20; i + 1 < 40; ++i) {
    const PlanarPose truth = Between(Planar(reference[i]), Planar(reference[i + 1]));
    const IcpTarget target(points(i), options);
    const IcpResult result = MatchIcp(points(i + 1), target, truth, options);
    ASSERT_TRUE(result.converged) << i;
    EXPECT_NEAR(result.T_target_source.x_m, truth.x_m, 0.06) << i;
    EXPECT_NEAR(result.T_target_source.y_m, truth.y_m, 0.06) << i;
    EXPECT_NEAR(result.T_target_source.theta_rad, truth.theta_rad, 1 * kDeg) << i;
    ++matched;
  }
  EXPECT_EQ(matched, 19);
}

struct WholeLog {
  std::vector<StampedPose> estimate_poses;  // at every scan
  std::vector<StampedPose> odometry_poses;
  eval::TrajectoryMetrics slam;
  eval::TrajectoryMetrics odometry;
  SlamQuality quality;
};

// The whole log reconstructed with the options, and scored against the corrected reference.
WholeLog ReconstructWholeLog(const test::TempDir& dir, const ReconstructionOptions& options) {
  std::vector<std::string> warnings;
  SlamPipeline pipeline(options.slam, ReadLaserExtrinsic(dir / "bag", options, &warnings));
  ReconstructBag(dir / "bag", options, &pipeline, {});
  std::vector<StampedPose> estimate, odometry;
  for (const ScanRecord& scan : pipeline.scans()) {
    estimate.push_back(StampedPoseFromPlanar(scan.stamp_ns, scan.T_world_base));
    odometry.push_back(StampedPoseFromPlanar(scan.stamp_ns, *scan.T_odom_base));
  }
  const std::vector<StampedPose> reference = bag::ReadTumTrajectory(dir / "ref.tum");
  const eval::TrajectoryMetrics slam = eval::EvaluateTrajectory(estimate, reference, {});
  const eval::TrajectoryMetrics odometry_metrics =
      eval::EvaluateTrajectory(odometry, reference, {});
  return {std::move(estimate), std::move(odometry), slam, odometry_metrics, pipeline.quality()};
}

TEST(CarmenSlam, AcesWholeLogMeetsAccuracyTargets) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(littermap::test::ImportCarmen("aces", 1, dir.path()));
  const WholeLog log = ReconstructWholeLog(dir, {});
  EXPECT_EQ(log.slam.associated_poses, 440u);
  // Measured on this log with seed 1: ATE 0.069 m, RPE 0.041 m, odometry ATE 10.4 m. The targets
  // of the issue (0.10 m, 0.05 m) are the bounds.
  EXPECT_LE(log.slam.ate_rmse_m, 0.10);
  EXPECT_LE(log.slam.rpe_trans_mean_m, 0.05);
  EXPECT_LT(log.slam.ate_rmse_m, log.odometry.ate_rmse_m / 20);
  EXPECT_GE(log.quality.loops_accepted, 10u);
}

TEST(CarmenSlam, ScanAlignmentBringsTheIntelLabCloserToTheReference) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(littermap::test::ImportCarmen("intel", 1, dir.path()));
  ReconstructionOptions without;
  without.slam.alignment_mode = AlignmentMode::kOff;
  const WholeLog before = ReconstructWholeLog(dir, without);
  const WholeLog after = ReconstructWholeLog(dir, {});  // a level laser: auto aligns
  EXPECT_EQ(before.quality.alignment.rounds, 0);
  EXPECT_EQ(after.quality.alignment.rounds, 4);
  EXPECT_GT(after.quality.alignment.pairs_matched, 2000u);
  // Measured with seed 1: ATE 0.068 -> 0.058 m, RPE 0.037 -> 0.034 m. Each must improve by at
  // least 5 %, well beyond the reference's own noise on a change of poses this small.
  EXPECT_LT(after.slam.ate_rmse_m, 0.95 * before.slam.ate_rmse_m);
  EXPECT_LT(after.slam.rpe_trans_mean_m, 0.95 * before.slam.rpe_trans_mean_m);
  EXPECT_LE(after.slam.ate_rmse_m, 0.10);

  // littermap's poses lay the lab's scans over each other more consistently than the
  // reference's, and the odometry's smear them. Measured: 21,917 / 26,436 / 72,806 cells of 5 cm
  // (ratios 0.83 and 2.75 to the reference).
  bag::WriteTumTrajectory(dir / "littermap.tum", after.estimate_poses);
  bag::WriteTumTrajectory(dir / "odometry.tum", after.odometry_poses);
  const auto maps =
      MeasureTrajectoryMaps(dir / "bag",
                            {(dir / "littermap.tum").string(), (dir / "ref.tum").string(),
                             (dir / "odometry.tum").string()},
                            {});
  ASSERT_EQ(maps.size(), 3u);
  for (const eval::MapSharpness& map : maps) {
    EXPECT_EQ(map.scans, 910u);
    EXPECT_EQ(map.scans_drawn, 910u);
  }
  EXPECT_LT(maps[0].occupied_cells, 0.95 * static_cast<double>(maps[1].occupied_cells));
  EXPECT_GT(maps[2].occupied_cells, 2 * maps[1].occupied_cells);
}

// The raw MIT CSAIL log with the robot's own odometry, graded by the benchmark's verified
// relations (Kuemmerle et al. 2009), not by another SLAM system's poses.
TEST(CarmenSlam, CsailRawWholeLogBeatsCartographerOnTheVerifiedRelations) {
  test::TempDir dir;
  const auto log = std::filesystem::path(LITTERMAP_DATASETS_DIR) / "carmen-raw" / "csail.clf.gz";
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  importers::ImportCarmenLog(log, dir / "bag");
  std::vector<double> stamps_s;
  for (const auto& scan : importers::ReadCarmenLog(log).scans) stamps_s.push_back(scan.timestamp_s);
  const auto relations = eval::ReadPoseRelations(log.parent_path() / "csail.relations");
  const auto grade = [&](const ReconstructionOptions& options) {
    std::vector<std::string> warnings;
    SlamPipeline pipeline(options.slam, ReadLaserExtrinsic(dir / "bag", options, &warnings));
    ReconstructBag(dir / "bag", options, &pipeline, {});
    std::vector<PlanarPose> trajectory;
    for (const ScanRecord& scan : pipeline.scans()) trajectory.push_back(scan.T_world_base);
    return std::pair{eval::EvaluatePoseRelations(trajectory, stamps_s, relations, {}),
                     pipeline.quality()};
  };
  ReconstructionOptions unrefined;
  unrefined.slam.refine_scans = false;
  const auto [before, before_quality] = grade(unrefined);
  const auto [after, after_quality] = grade({});
  EXPECT_EQ(before_quality.refinement.rounds, 0);
  EXPECT_EQ(after_quality.refinement.rounds, 4);
  ASSERT_EQ(after.used, 1172u) << "every relation has both ends in the raw log";
  // Measured: 0.0277 m without the scan refinement, 0.0268 m with it; Cartographer's published
  // figure is 0.032 m. No wrong loop: no relation off by more than half a metre (the largest is
  // 0.30 m).
  EXPECT_LE(after.component.translation_m.mean, 0.032);
  EXPECT_LT(after.component.translation_m.mean, before.component.translation_m.mean);
  EXPECT_EQ(after.component.over_large_error, 0u);
}

// freiburg-campus outdoors, with two odometry noise seeds that used to lose the map: with seed 2
// the robot drives a street again 400 m along the graph after a long excursion and its open view
// overlays 60-85 % of the scan, too little for a far loop alone (a confirmed one now: ATE 0.37 ->
// 0.22 m); with seed 5 eight scans of an open stretch match nothing and the odometry alone turns
// the heading 12 degrees wrong, beyond the searches' windows (widened now, and a wide match
// confirmed: 9.5 -> 0.30 m). The bound: the noise-free odometry's ATE (0.29 m; the reference's
// own scans move it 0.48 m when settled, bench/slam_carmen.sh) + 0.03 m.
TEST(CarmenSlam, FreiburgCampusClosesItsLoopsWhateverTheOdometryNoise) {
  for (const int seed : {2, 5}) {
    test::TempDir dir;
    ASSERT_NO_FATAL_FAILURE(littermap::test::ImportCarmen("freiburg-campus", seed, dir.path()));
    const WholeLog log = ReconstructWholeLog(dir, {});
    EXPECT_LE(log.slam.ate_rmse_m, 0.32) << "seed " << seed;
    EXPECT_LE(log.slam.ate_max_m, 1.5) << "seed " << seed;
    EXPECT_GE(log.quality.loops_confirmed, 1u) << "seed " << seed;
  }
}

}  // namespace
}  // namespace littermap::reconstruct

// The tracker fuses each match with the prediction: where a scan leaves a direction open, the
// prediction holds the pose there instead of letting the matcher slide along it.

#include "reconstruct/tracker.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/scan_points.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

// A round column (a 72-gon, radius 1 m): it looks the same from every point of a circle around
// its centre, so a scan of it alone fixes range and bearing to the centre but not the robot's
// place on that circle.
std::vector<test::Segment> Column() {
  const Eigen::Vector2d centre(4, 2.5);
  std::vector<test::Segment> walls;
  const int sides = 72;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * i / sides;
    const double b = 2 * std::numbers::pi * (i + 1) / sides;
    walls.push_back({centre + Eigen::Vector2d(std::cos(a), std::sin(a)),
                     centre + Eigen::Vector2d(std::cos(b), std::sin(b))});
  }
  return walls;
}

// Drives 8 m along x past the column with exact odometry and noisy ranges; returns the largest
// position error of the tracked poses.
double LargestErrorPassingColumn(const TrackerOptions& options) {
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map);
  std::mt19937_64 engine(11);
  std::normal_distribution<double> range_noise(0, 0.02);
  double largest = 0;
  for (int i = 0; i <= 160; ++i) {
    const PlanarPose truth{0.05 * i, 0, 0};
    LaserScan scan = test::ScanFrom(Column(), truth);
    for (float& r : scan.ranges_m) {
      if (r < scan.range_max_m) r = static_cast<float>(r + range_noise(engine));
    }
    scan.stamp_ns = static_cast<TimestampNs>(i) * 100'000'000;
    TrackInput input;
    input.stamp_ns = scan.stamp_ns;
    input.T_odom_base = truth;
    input.points_base = VoxelDownsample(ScanToPoints(scan, {}, {}).points_base, 0.05);
    const TrackStep step = tracker.Track(static_cast<std::size_t>(i), input);
    largest = std::max(
        largest, std::hypot(step.T_world_base.x_m - truth.x_m, step.T_world_base.y_m - truth.y_m));
  }
  return largest;
}

TEST(Tracker, PredictionHoldsThePoseWhereTheScanLeavesItOpen) {
  // Exact odometry: all error comes from the matches. With a prediction too weak to matter the
  // noisy column scans let the pose wander around the column (measured 2.7 m over 8 m); fused
  // with the odometry since the last key frame it stays close (measured 0.24 m: each key frame
  // still starts from a pose that slid a little).
  TrackerOptions without;
  without.odometry_sigma_m = 100;
  without.odometry_sigma_rad = 100;
  const double wandered_m = LargestErrorPassingColumn(without);
  EXPECT_GT(wandered_m, 1.0);
  EXPECT_LT(LargestErrorPassingColumn(TrackerOptions{}), wandered_m / 5);
}

// Routine 3 through a stand-in for the RGB-D tracker: it answers with a fixed pose and records
// what the tracker tells it.
class FixedRgbd final : public RgbdFallback {
 public:
  explicit FixedRgbd(std::optional<PlanarPose> pose) : pose_(pose) {}
  std::optional<PlanarPose> AlignAt(const TrackInput&, const PlanarPose&,
                                    const KeyFrameMap&) override {
    ++asked_;
    return pose_;
  }
  void OnTracked(const TrackInput&, const TrackStep& step, const KeyFrameMap&) override {
    routines_.push_back(step.routine);
  }
  int asked_ = 0;
  std::vector<Routine> routines_;

 private:
  std::optional<PlanarPose> pose_;
};

// Two scans in the room, then one without echoes (the laser on the ground) from `odometry`,
// turned by a gyro or by the wheels.
TrackStep TrackIntoBlindScan(FixedRgbd* rgbd, const PlanarPose& odometry, bool gyro = false) {
  TrackerOptions options;
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map, rgbd);
  for (int i = 0; i < 2; ++i) {
    const PlanarPose pose{0.1 * i, 0, 0};
    tracker.Track(
        static_cast<std::size_t>(i),
        {static_cast<TimestampNs>(i) * 100'000'000, test::RoomPoints(pose), pose, {}, gyro});
  }
  return tracker.Track(2, {200'000'000, {}, odometry, {}, gyro});
}

TEST(Tracker, RoutineThreePlacesAScanTheLaserCannotWhenItsPoseAgreesWithThePrediction) {
  FixedRgbd rgbd(PlanarPose{0.22, 0.01, 0.02});  // 2 cm off the odometry's 0.2 m
  const TrackStep step = TrackIntoBlindScan(&rgbd, {0.2, 0, 0});
  EXPECT_EQ(rgbd.asked_, 1);  // the laser placed the two room scans itself
  EXPECT_EQ(step.routine, Routine::kRgbd);
  EXPECT_NEAR(step.T_world_base.x_m, 0.22, 1e-9);  // the RGB-D pose as measured
  EXPECT_NEAR(step.T_world_base.theta_rad, 0.02, 1e-9);
  ASSERT_EQ(rgbd.routines_.size(), 3u);  // told every outcome
  EXPECT_EQ(rgbd.routines_[0], Routine::kGlobal);
  EXPECT_EQ(rgbd.routines_[2], Routine::kRgbd);
}

TEST(Tracker, RoutineThreeTakesItsHeadingFromAGyroAndItsPositionFromTheCamera) {
  FixedRgbd rgbd(PlanarPose{0.22, 0.01, 0.02});
  const TrackStep step = TrackIntoBlindScan(&rgbd, {0.2, 0, 0}, true);
  EXPECT_EQ(step.routine, Routine::kRgbd);
  EXPECT_NEAR(step.T_world_base.x_m, 0.22, 1e-9);  // the wheels may have slipped: not fused
  EXPECT_NEAR(step.T_world_base.y_m, 0.01, 1e-9);
  // The gyro's 1 mrad against the camera's 20 mrad: the predicted heading stays (0, within the
  // 2 mrad the room scans left), not the camera's 0.02 rad.
  EXPECT_NEAR(step.T_world_base.theta_rad, 0, 0.003);
}

TEST(Tracker, RoutineThreeRejectsAPoseNeitherTheLaserNorThePredictionConfirms) {
  FixedRgbd far(PlanarPose{3.0, 2.0, 1.0});  // metres and radians from the prediction
  EXPECT_EQ(TrackIntoBlindScan(&far, {0.2, 0, 0}).routine, Routine::kOdometryOnly);
  FixedRgbd none(std::nullopt);  // no frame or no alignment
  const TrackStep step = TrackIntoBlindScan(&none, {0.2, 0, 0});
  EXPECT_EQ(step.routine, Routine::kOdometryOnly);
  EXPECT_NEAR(step.T_world_base.x_m, 0.2, 0.02);  // the odometry's step from the last pose
}

// Drives the room at 0.2 m per scan (0.1 s apart) along x with exact odometry but for what
// `odometry_of` makes of it; returns the tracker's last step and its largest position error.
struct Drive {
  TrackStep last;
  double largest_error_m = 0;
  std::size_t arbitrated = 0;
};
template <typename OdometryOf>
Drive DriveRoom(int scans, OdometryOf odometry_of, bool gyro = false) {
  TrackerOptions options;
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map);
  Drive drive;
  for (int i = 0; i < scans; ++i) {
    const PlanarPose truth{1.0 + 0.2 * i, 0.5, 0};
    TrackInput input{static_cast<TimestampNs>(i) * 100'000'000,
                     test::RoomPoints(truth),
                     odometry_of(i, truth),
                     {},
                     gyro};
    drive.last = tracker.Track(static_cast<std::size_t>(i), input);
    drive.largest_error_m =
        std::max(drive.largest_error_m, std::hypot(drive.last.T_world_base.x_m - truth.x_m + 1.0,
                                                   drive.last.T_world_base.y_m - truth.y_m + 0.5));
  }
  drive.arbitrated = tracker.odometry_arbitrated();
  return drive;
}

// The raw MIT CSAIL log's odometry stands still for a few scans while the robot drives on, then
// catches up by a metre in one step. Matched from the odometry's jump the scan lands implausibly
// far from it; matched from constant velocity it lands where the robot is, and that wins.
TEST(Tracker, OdometryThatStallsAndCatchesUpIsOverruledByTheLaser) {
  const Drive drive = DriveRoom(14, [](int i, const PlanarPose& truth) {
    PlanarPose odometry = truth;
    if (i >= 6 && i < 10) odometry.x_m = 1.0 + 0.2 * 5;  // stalled at scan 5
    return odometry;
  });
  EXPECT_GE(drive.arbitrated, 1u);
  EXPECT_LT(drive.largest_error_m, 0.05);
}

// Without the laser's say the same stall and jump would put the pose a metre ahead: the
// constant-velocity guess is only taken where the laser confirms it.
TEST(Tracker, OdometryTheLaserConfirmsIsKeptEvenWhenItDisagreesWithConstantVelocity) {
  // The robot stops dead at scan 6: constant velocity overshoots, the odometry is right.
  const Drive drive = DriveRoom(12, [](int i, const PlanarPose& truth) {
    (void)i;
    return truth;
  });
  EXPECT_EQ(drive.arbitrated, 0u);
  EXPECT_LT(drive.largest_error_m, 0.05);
}

// Three scans in the room while the robot drives straight, then one from a robot turned
// 6 degrees (a wrong match in a park's few trunks would look like this) while the odometry says
// it did not turn, its heading a gyro's or the wheels'.
TrackStep TrackIntoUnturnedOdometry(bool gyro) {
  TrackerOptions options;
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map);
  for (int i = 0; i < 3; ++i) {
    const PlanarPose pose{1.0 + 0.1 * i, 0.5, 0};
    tracker.Track(
        static_cast<std::size_t>(i),
        {static_cast<TimestampNs>(i) * 100'000'000, test::RoomPoints(pose), pose, {}, gyro});
  }
  const PlanarPose turned{1.3, 0.5, 6 * std::numbers::pi / 180};
  return tracker.Track(3,
                       {300'000'000, test::RoomPoints(turned), PlanarPose{1.3, 0.5, 0}, {}, gyro});
}

TEST(Tracker, AMatchThatDisagreesWithTheGyroIsNotTaken) {
  const TrackStep step = TrackIntoUnturnedOdometry(true);
  EXPECT_NE(step.routine, Routine::kGlobal);
  EXPECT_NEAR(step.T_world_base.theta_rad, 0, 0.002);  // the gyro's, not the match's 0.1 rad
  // With wheels alone the laser is believed (they may have slipped).
  const TrackStep believed = TrackIntoUnturnedOdometry(false);
  EXPECT_EQ(believed.routine, Routine::kGlobal);
  EXPECT_NEAR(believed.T_world_base.theta_rad, 6 * std::numbers::pi / 180, 0.01);
}

// Wheels that turned 15 degrees too far in one step: a match that overlays the room's walls
// almost perfectly takes the heading back, beyond the usual 7-degree correction limit.
TEST(Tracker, AWellOverlaidMatchCorrectsAHeadingGlitchOfTheWheels) {
  const double glitch_rad = 15 * std::numbers::pi / 180;
  const Drive drive = DriveRoom(10, [&](int i, const PlanarPose& truth) {
    PlanarPose odometry = truth;
    if (i >= 5) odometry.theta_rad += glitch_rad;  // the wheels' heading is off from scan 5 on
    return odometry;
  });
  EXPECT_NEAR(drive.last.T_world_base.theta_rad, 0, 0.01);
  EXPECT_LT(drive.largest_error_m, 0.05);
}

// Three level scans in the room, then one whose echoes are half the room's and half a ground
// arc 1.5 m ahead (the scan plane on a root): matched, it overlays about half of its echoes.
TrackStep TrackIntoGroundArc(const Tilt& tilt, std::size_t arc_points) {
  TrackerOptions options;
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map);
  for (int i = 0; i < 3; ++i) {
    const PlanarPose pose{1.0 + 0.1 * i, 0.5, 0};
    tracker.Track(static_cast<std::size_t>(i), {static_cast<TimestampNs>(i) * 100'000'000,
                                                test::RoomPoints(pose), pose, Tilt{}, true});
  }
  const PlanarPose pose{1.3, 0.5, 0};
  Points2 points = test::RoomPoints(pose);
  const std::size_t room_points = points.size();
  for (std::size_t k = 0; k < arc_points; ++k) {
    const double a = -0.8 + 1.6 * static_cast<double>(k) / static_cast<double>(arc_points);
    points.emplace_back(1.5 * std::cos(a), 1.5 * std::sin(a));
  }
  EXPECT_GT(room_points, 40u);
  return tracker.Track(3, {300'000'000, std::move(points), pose, tilt, true});
}

TEST(Tracker, TiltedBeyondLevelOnlyAMatchOverlayingMostOfTheScanIsTheLasers) {
  const double tilt_rad = 10 * std::numbers::pi / 180;
  const std::size_t half = test::RoomPoints({1.3, 0.5, 0}).size();
  // Level, half the echoes on the map is a match (the thesis's ratio is 0.35) ...
  const TrackStep level = TrackIntoGroundArc(Tilt{}, half);
  EXPECT_EQ(level.routine, Routine::kGlobal);
  EXPECT_NEAR(level.matching_ratio, 0.5, 0.1);
  // ... tilted 10 degrees it is not, and the odometry places the scan ...
  const TrackStep tilted = TrackIntoGroundArc(Tilt{0, tilt_rad}, half);
  EXPECT_EQ(tilted.routine, Routine::kOdometryOnly);
  EXPECT_NEAR(tilted.T_world_base.x_m, 0.3, 0.01);
  // ... unless the match overlays most of the scan.
  const TrackStep overlaid = TrackIntoGroundArc(Tilt{tilt_rad, 0}, half / 10);
  EXPECT_EQ(overlaid.routine, Routine::kGlobal);
  EXPECT_GE(overlaid.matching_ratio, 0.6);
}

}  // namespace
}  // namespace littermap::reconstruct

// The SLAM pipeline on synthetic scans: bad input (scans without echoes, time going backwards,
// duplicate stamps, missing odometry) is counted and handled, never a crash.

#include "reconstruct/slam_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

// Every loop record of a finished run is settled and joins an earlier key frame to a later one.
void ExpectLoopRecordsSettled(const SlamPipeline& pipeline) {
  for (const LoopRecord& record : pipeline.loops()) {
    EXPECT_NE(record.outcome, LoopOutcome::kTentative);
    EXPECT_LT(record.from_key_frame, record.to_key_frame);
    EXPECT_LT(record.from_stamp_ns, record.to_stamp_ns);
  }
}

// The loop counters are the records' sums: one record of every kind and outcome a run can end
// with, and each counter holds exactly the records it names.
TEST(SlamPipeline, LoopCountersAreTheSumsOfTheRecords) {
  const auto record = [](LoopKind kind, LoopOutcome outcome, bool confirmed = false) {
    LoopRecord r;
    r.kind = kind;
    r.outcome = outcome;
    r.confirmed = confirmed;
    return r;
  };
  using K = LoopKind;
  using O = LoopOutcome;
  const std::vector<LoopRecord> records = {
      record(K::kScan, O::kAccepted),
      record(K::kScan, O::kAccepted, true),  // a confirmed tentative match
      record(K::kScan, O::kAccepted),        // its confirmation
      record(K::kScan, O::kRejectedMatch),
      record(K::kScan, O::kRejectedMatch),
      record(K::kScan, O::kUnconfirmed),
      record(K::kScan, O::kRejectedDisagreement),
      record(K::kScan, O::kRejectedDegenerate),
      record(K::kScan, O::kRejectedDegenerate),
      record(K::kScan, O::kRejectedAfterOptimisation, true),  // confirmed, pruned at the end
      record(K::kScan, O::kRejectedInconsistent),
      record(K::kScan, O::kRejectedInconsistent),
      record(K::kCamera, O::kAccepted),
      record(K::kCamera, O::kRejectedDisagreement),
      record(K::kCamera, O::kRejectedAfterOptimisation),
      record(K::kCamera, O::kRejectedInconsistent),
      record(K::kLandmark, O::kAccepted),
      record(K::kLandmark, O::kAccepted),
      record(K::kLandmark, O::kRejectedAfterOptimisation),
  };
  SlamQuality q;
  q.loops_accepted = 99;  // whatever was there before is replaced
  TallyLoops(records, &q);
  EXPECT_EQ(q.loop_candidates, 12u);
  EXPECT_EQ(q.loops_accepted, 3u);
  EXPECT_EQ(q.loops_rejected_match, 3u);  // an unconfirmed match is a rejected one
  EXPECT_EQ(q.loops_rejected_disagreement, 1u);
  EXPECT_EQ(q.loops_rejected_degenerate, 2u);
  EXPECT_EQ(q.loops_rejected_after_optimisation, 1u);
  EXPECT_EQ(q.loops_rejected_inconsistent, 2u);
  EXPECT_EQ(q.loops_rejected(), 9u);
  EXPECT_EQ(q.loops_confirmed, 2u);
  EXPECT_EQ(q.camera_loops_found, 4u);
  EXPECT_EQ(q.camera_loops_accepted, 1u);
  EXPECT_EQ(q.camera_loops_rejected, 3u);
  EXPECT_EQ(q.landmark_loops_found, 3u);
  EXPECT_EQ(q.landmark_loops_accepted, 2u);
  EXPECT_EQ(q.landmark_loops_rejected, 1u);
}

LaserScan RoomScan(const PlanarPose& pose, TimestampNs stamp_ns) {
  LaserScan scan = test::ScanFrom(test::Room(), pose);
  scan.stamp_ns = stamp_ns;
  return scan;
}

TEST(SlamPipeline, BadScansAndStampsAreCountedNotFatal) {
  SlamPipeline pipeline({}, {});
  const TimestampNs step = 100'000'000;
  PlanarPose truth{2, 2, 0};
  TimestampNs t = step;
  for (int i = 0; i < 10; ++i, t += step) {
    pipeline.AddScan(RoomScan(truth, t), GyroOdometryPose{truth});
    truth = Compose(truth, {0.1, 0, 0.01});
  }
  LaserScan nan_scan = RoomScan(truth, t);
  for (float& r : nan_scan.ranges_m) r = std::numeric_limits<float>::quiet_NaN();
  pipeline.AddScan(nan_scan, GyroOdometryPose{truth});
  t += step;
  LaserScan max_range = RoomScan(truth, t);
  for (float& r : max_range.ranges_m) r = static_cast<float>(max_range.range_max_m);
  pipeline.AddScan(max_range, std::nullopt);                      // and no odometry either
  pipeline.AddScan(RoomScan(truth, t), GyroOdometryPose{truth});  // duplicate stamp
  pipeline.AddScan(RoomScan(truth, t - 3 * step), GyroOdometryPose{truth});  // back in time
  t += step;
  LaserScan no_beams;
  no_beams.stamp_ns = t;
  pipeline.AddScan(no_beams, GyroOdometryPose{truth});  // no beams at all
  t += step;
  pipeline.AddScan(RoomScan(truth, t), GyroOdometryPose{truth});
  pipeline.Finish();

  const SlamQuality& quality = pipeline.quality();
  EXPECT_EQ(quality.scans_in, 16u);
  EXPECT_EQ(quality.scans_without_echoes, 3u);
  EXPECT_EQ(quality.stamps_duplicate, 1u);
  EXPECT_EQ(quality.stamps_backwards, 1u);
  EXPECT_EQ(quality.odometry_missing, 1u);
  ASSERT_EQ(pipeline.scans().size(), 14u);  // a pose for every scan kept
  // The last scan is matched again and lands on the truth.
  const PlanarPose last = pipeline.scans().back().T_world_base;
  const PlanarPose expected = Between(PlanarPose{2, 2, 0}, truth);
  EXPECT_NEAR(last.x_m, expected.x_m, 0.01);
  EXPECT_NEAR(last.y_m, expected.y_m, 0.01);
  EXPECT_EQ(pipeline.scans().back().routine, Routine::kGlobal);
  EXPECT_FALSE(pipeline.map().empty());
}

TEST(SlamPipeline, MapDrawsTheWallsInRangeWhereTheyAre) {
  SlamOptions options;
  options.map_max_range_m = 6;
  SlamPipeline pipeline(options, {});
  // The first pose is the map's origin: the walls at x = -2.025 and 9.975, mid-cell.
  const PlanarPose pose{2.025, 2.025, 0};
  LaserScan scan = test::ScanFrom(test::Room(), pose, 1440);  // beams < 2 cm apart at 4 m
  scan.stamp_ns = 100'000'000;
  pipeline.AddScan(scan, GyroOdometryPose{pose});
  pipeline.Finish();
  const OccupancyGrid& map = pipeline.map();
  const double cell_m = options.grid.cell_size_m;
  const auto occupied = [&](double x, int j) {
    return map.LogOdds(map.CellOf({x, (j + 0.5) * cell_m})) > 0;
  };
  // y from -1.5 m to 3 m: within 6 m of the near wall. One echo is kept per cell of the scan's
  // own frame, in whole centimetres, so a wall cell may lose its echo to a neighbour: the wall
  // is an unbroken line to within one cell, and nothing is drawn off it.
  int near_cells = 0;
  for (int j = -30; j < 60; ++j) {
    near_cells += occupied(-2.025, j);
    EXPECT_TRUE(occupied(-2.025, j - 1) || occupied(-2.025, j) || occupied(-2.025, j + 1))
        << "gap at y " << (j + 0.5) * cell_m;
    EXPECT_FALSE(occupied(-2.025 + cell_m, j)) << "y " << (j + 0.5) * cell_m;
    EXPECT_FALSE(occupied(9.975, j)) << "beyond map_max_range_m, y " << (j + 0.5) * cell_m;
  }
  EXPECT_GE(near_cells, 60);  // of 90
}

// A short drive through the room, its scans with or without the base's tilt.
SlamQuality DriveThroughTheRoom(AlignmentMode mode, const std::optional<Tilt>& tilt) {
  SlamOptions options;
  options.alignment_mode = mode;
  SlamPipeline pipeline(options, {});
  PlanarPose truth{2, 2, 0};
  const TimestampNs step = 100'000'000;
  for (int i = 0; i < 30; ++i) {
    pipeline.AddScan(RoomScan(truth, (i + 1) * step), GyroOdometryPose{truth}, tilt);
    truth = Compose(truth, {0.2, 0, 0.02});
  }
  pipeline.Finish();
  return pipeline.quality();
}

TEST(SlamPipeline, ScanAlignmentRunsForALevelScannerUnlessAskedOtherwise) {
  const Tilt level_enough{0.001, -0.002};  // an IMU was there: the ground may be uneven
  EXPECT_EQ(DriveThroughTheRoom(AlignmentMode::kAuto, std::nullopt).alignment.rounds, 4);
  EXPECT_EQ(DriveThroughTheRoom(AlignmentMode::kAuto, level_enough).alignment.rounds, 0);
  EXPECT_EQ(DriveThroughTheRoom(AlignmentMode::kOn, level_enough).alignment.rounds, 4);
  EXPECT_EQ(DriveThroughTheRoom(AlignmentMode::kOff, std::nullopt).alignment.rounds, 0);
  const SlamQuality aligned = DriveThroughTheRoom(AlignmentMode::kAuto, std::nullopt);
  EXPECT_TRUE(aligned.alignment.usable);
  EXPECT_GT(aligned.alignment.pairs_matched, 0u);
}

// Out 45 m and back with the laser blind in between (the walls out of its reach), then back over
// the start, where the end of the run's wide search closes the loop. The odometry turns
// far_turn_error_rad too far at the far end and home_turn_error_rad too far at home; gyro: the
// odometry says a gyro turned it. The final scan alignment is left out (tested on its own).
struct OutAndBack {
  PlanarPose start{2, 2, 0};
  PlanarPose truth = start;  // where the run ended
};

OutAndBack DriveOutAndBack(SlamPipeline* pipeline, double far_turn_error_rad,
                           double home_turn_error_rad, bool gyro) {
  OutAndBack run;
  PlanarPose odometry = run.start;
  TimestampNs stamp_ns = 0;
  const auto scan_and_move = [&](bool laser_sees, const PlanarPose& step, double odometry_turn) {
    stamp_ns += 500'000'000;
    LaserScan scan = RoomScan(run.truth, stamp_ns);
    if (!laser_sees) {
      std::fill(scan.ranges_m.begin(), scan.ranges_m.end(),
                std::numeric_limits<float>::quiet_NaN());
    }
    pipeline->AddScan(scan, GyroOdometryPose{odometry, gyro, 0});
    run.truth = Compose(run.truth, step);
    odometry = Compose(odometry, {step.x_m, step.y_m, step.theta_rad + odometry_turn});
  };
  for (int i = 0; i < 5; ++i) scan_and_move(true, {0.6, 0, 0}, 0);
  for (int leg = 0; leg < 2; ++leg) {
    for (int i = 0; i < 45; ++i) scan_and_move(false, {1, 0, 0}, 0);
    const double error = (leg == 0 ? far_turn_error_rad : home_turn_error_rad) / 3;
    for (int i = 0; i < 3; ++i) scan_and_move(false, {0, 0, std::numbers::pi / 3}, error);
  }
  for (int i = 0; i < 4; ++i) scan_and_move(true, {-0.6, 0, 0}, 0);  // back over the start
  pipeline->Finish();
  return run;
}

SlamOptions OutAndBackOptions() {
  SlamOptions options;
  options.landmarks = false;
  options.alignment_mode = AlignmentMode::kOff;
  options.loops.search_radius_m = 1;
  options.wide_loop_search_every_m = 1000;
  return options;
}

// Routine 3 through a stand-in for the RGB-D tracker that finds the camera where the odometry
// predicted it: every scan the laser cannot place, the camera does.
class CameraAtThePrediction final : public RgbdFallback {
 public:
  std::optional<PlanarPose> AlignAt(const TrackInput&, const PlanarPose& T_world_base_predicted,
                                    const KeyFrameMap&) override {
    return T_world_base_predicted;
  }
  void OnTracked(const TrackInput&, const TrackStep&, const KeyFrameMap&) override {}
};

// The heading-only edges of a run's final graph.
std::vector<PoseGraphEdge> GyroTurnEdges(const SlamPipeline& pipeline) {
  std::vector<PoseGraphEdge> turns;
  std::copy_if(pipeline.edges().begin(), pipeline.edges().end(), std::back_inserter(turns),
               [](const PoseGraphEdge& edge) { return edge.heading_only; });
  return turns;
}

// The steps the camera placed took their path through poses their information does not speak for
// (a soft heading floor, so that a loop's correction goes there rather than where the laser
// held), but a gyro turned them: on flat ground too, each such step gets the gyro's turn as an
// edge of its own. Steps the odometry alone placed, or wheels without a gyro, get none.
TEST(SlamPipeline, StepsTheCameraPlacedKeepTheGyrosTurn) {
  CameraAtThePrediction camera;
  SlamPipeline with_camera(OutAndBackOptions(), {}, &camera);
  DriveOutAndBack(&with_camera, 0.02, 0, true);
  std::size_t placed_by_camera = 0;
  for (const ScanRecord& record : with_camera.scans()) {
    placed_by_camera += record.routine == Routine::kRgbd ? 1 : 0;
  }
  EXPECT_GE(placed_by_camera, 90u);  // the blind legs and turns
  const std::vector<PoseGraphEdge> turns = GyroTurnEdges(with_camera);
  EXPECT_GE(turns.size(), 40u);
  // Each is the odometry's (the gyro's) turn between its key frames.
  const auto odometry_heading = [&](std::size_t key_frame) {
    for (const ScanRecord& record : with_camera.scans()) {
      if (record.key_frame == key_frame && record.T_odom_base) {
        return record.T_odom_base->theta_rad;
      }
    }
    ADD_FAILURE() << "no scan of key frame " << key_frame;
    return 0.0;
  };
  for (const PoseGraphEdge& turn : turns) {
    EXPECT_NEAR(WrapAngle(turn.T_from_to.theta_rad -
                          (odometry_heading(turn.to) - odometry_heading(turn.from))),
                0, 1e-9);
  }

  SlamPipeline odometry_alone(OutAndBackOptions(), {});
  DriveOutAndBack(&odometry_alone, 0.02, 0, true);
  EXPECT_TRUE(GyroTurnEdges(odometry_alone).empty());
  CameraAtThePrediction camera_without_gyro;
  SlamPipeline wheels_alone(OutAndBackOptions(), {}, &camera_without_gyro);
  DriveOutAndBack(&wheels_alone, 0.02, 0, false);
  EXPECT_TRUE(GyroTurnEdges(wheels_alone).empty());
}

// A survey that comes home after a long stretch the laser saw nothing of, placed by odometry that
// drifted 2.7 m sideways (the wheels turn 0.06 rad too far at the far end and as much too little
// at home): the nearest-candidate search reaches 1 m here and the run's wide searches are spaced
// further apart than the run is long, so only the search at the end of the run, back at the
// start, can close the loop.
TEST(SlamPipeline, TheEndOfTheRunGetsAWideLoopSearch) {
  SlamPipeline pipeline(OutAndBackOptions(), {});
  const OutAndBack run = DriveOutAndBack(&pipeline, 0.06, -0.06, false);

  EXPECT_EQ(pipeline.quality().loops_accepted, 1u);
  ExpectLoopRecordsSettled(pipeline);
  // The loop is the last key frame's, back to one of the first, 90 m along the path.
  const auto accepted =
      std::find_if(pipeline.loops().begin(), pipeline.loops().end(),
                   [](const LoopRecord& r) { return r.outcome == LoopOutcome::kAccepted; });
  ASSERT_NE(accepted, pipeline.loops().end());
  EXPECT_EQ(accepted->kind, LoopKind::kScan);
  EXPECT_LE(accepted->from_stamp_ns, 2'500'000'000);
  EXPECT_EQ(accepted->to_stamp_ns, pipeline.scans().back().stamp_ns);
  ASSERT_TRUE(accepted->matching_ratio.has_value());
  EXPECT_GE(*accepted->matching_ratio, LoopCloserOptions{}.min_wide_matching_ratio);
  ASSERT_TRUE(accepted->weakest_sigma_m.has_value());
  EXPECT_LE(*accepted->weakest_sigma_m, LoopCloserOptions{}.max_weakest_sigma_m);
  // Where the last scan was, in the frame of the first (the world frame of the run).
  const PlanarPose expected =
      Between(run.start, Compose(run.truth, Inverse(PlanarPose{-0.6, 0, 0})));
  const PlanarPose& last = pipeline.scans().back().T_world_base;
  EXPECT_LT(std::hypot(last.x_m - expected.x_m, last.y_m - expected.y_m), 0.1);
  EXPECT_LT(std::abs(WrapAngle(last.theta_rad - expected.theta_rad)), 0.02);
}

// With a gyro turning the odometry all the way, a loop must agree with the gyro's heading: here
// the "gyro" turned too far at the far end, so the true loop at home disagrees with it by that
// much. Within the gyro's bound (0.03 rad + 0.0002 rad/s, 0.04 rad over this run) a loop 0.02 rad
// off is accepted; one 0.06 rad off is rejected as a disagreement.
TEST(SlamPipeline, ALoopMustAgreeWithTheGyroOverItsPath) {
  SlamPipeline within(OutAndBackOptions(), {});
  DriveOutAndBack(&within, 0.02, 0, true);
  EXPECT_GE(within.quality().loops_accepted, 1u);
  EXPECT_EQ(within.quality().loops_rejected_disagreement, 0u);

  SlamPipeline beyond(OutAndBackOptions(), {});
  DriveOutAndBack(&beyond, 0.06, 0, true);
  EXPECT_EQ(beyond.quality().loops_accepted, 0u);
  EXPECT_GE(beyond.quality().loops_rejected_disagreement, 1u);
  ExpectLoopRecordsSettled(beyond);
}

// The room with five posts (24-gons, 0.15 m radius: landmarks), driven around once and on until
// the scan matcher closes a loop; returns how many landmark sightings hold key frames in the final
// graph. tilt: an IMU reported the base level (outdoors); gyro: the odometry's heading is a
// gyro's; range_m: the scanner's reach.
std::size_t LandmarkSightingsInTheGraph(bool tilt, bool gyro, double range_m) {
  std::vector<test::Segment> walls = test::Room();
  for (const Eigen::Vector2d& centre :
       {Eigen::Vector2d(3, 1), Eigen::Vector2d(9, 1.2), Eigen::Vector2d(4, 6),
        Eigen::Vector2d(10, 5.8), Eigen::Vector2d(8, 3.5)}) {
    for (int i = 0; i < 24; ++i) {
      const auto corner = [&](int k) {
        const double a = 2 * std::numbers::pi * k / 24;
        return Eigen::Vector2d(centre + 0.15 * Eigen::Vector2d(std::cos(a), std::sin(a)));
      };
      walls.push_back({corner(i), corner(i + 1)});
    }
  }
  SlamPipeline pipeline(SlamOptions{}, {});
  const std::vector<Eigen::Vector2d> corners = {{2, 2.2}, {10.5, 2.2}, {10.5, 4.8}, {2, 4.8}};
  PlanarPose pose{2, 2.2, 0};
  TimestampNs stamp_ns = 0;
  for (int leg = 0; leg < 6; ++leg) {
    const Eigen::Vector2d to = corners[(leg + 1) % corners.size()];
    const double heading = std::atan2(to.y() - pose.y_m, to.x() - pose.x_m);
    pose.theta_rad = heading;
    while (std::hypot(to.x() - pose.x_m, to.y() - pose.y_m) > 0.05) {
      const double step = std::min(0.2, std::hypot(to.x() - pose.x_m, to.y() - pose.y_m));
      pose = {pose.x_m + step * std::cos(heading), pose.y_m + step * std::sin(heading), heading};
      LaserScan scan = test::ScanFrom(walls, pose, 720);
      scan.stamp_ns = stamp_ns += 100'000'000;
      scan.range_max_m = range_m;
      for (float& r : scan.ranges_m) {
        if (r > range_m) r = std::numeric_limits<float>::infinity();
      }
      pipeline.AddScan(scan, GyroOdometryPose{pose, gyro, 0},
                       tilt ? std::optional<Tilt>(Tilt{0, 0}) : std::nullopt);
    }
  }
  pipeline.Finish();
  EXPECT_GT(pipeline.quality().loops_accepted, 0u);
  ExpectLoopRecordsSettled(pipeline);
  std::size_t sightings = 0;
  for (const ScanRecord& record : pipeline.scans()) sightings += record.landmark_sightings;
  return sightings;
}

// Outdoors (an IMU and a gyro's heading) the sightings hold the graph from the start, whatever the
// scanner's range; indoors only after a loop closed on the landmarks (none here).
// Wheels alone (no gyro) can slip by degrees over a root: then the sightings wait for a landmark
// loop as well.
TEST(SlamPipeline, LandmarkSightingsHoldTheGraphOutdoorsFromTheStart) {
  EXPECT_GT(LandmarkSightingsInTheGraph(true, true, 30), 0u);
  EXPECT_GT(LandmarkSightingsInTheGraph(true, true, 5.6), 0u);
  EXPECT_EQ(LandmarkSightingsInTheGraph(false, true, 30), 0u);
  EXPECT_EQ(LandmarkSightingsInTheGraph(true, false, 30), 0u);
}

// A 30 m x 10 m loop between rows of posts (24-gons, 0.15 m radius) that a 4 m scanner sees only
// along the two long sides; the short sides and the turns at the corners are blind (no echoes),
// and in each turn the "gyro" turns 0.01 rad too far. Driven once around and on past the start,
// where a loop closes. Returns the largest heading error of the key frames along the first long
// side, which the laser and the gyro held.
double HeldSideHeadingError(const SlamOptions& options) {
  std::vector<test::Segment> walls;
  for (double x = 0; x <= 30; x += 2) {
    for (const double y : {-1.5, 1.5, 8.5, 11.5}) {
      for (int i = 0; i < 24; ++i) {
        const auto corner = [&](int k) {
          const double a = 2 * std::numbers::pi * k / 24;
          return Eigen::Vector2d(Eigen::Vector2d(x + (y > 5 ? 1 : 0), y) +
                                 0.15 * Eigen::Vector2d(std::cos(a), std::sin(a)));
        };
        walls.push_back({corner(i), corner(i + 1)});
      }
    }
  }
  SlamPipeline pipeline(options, {});
  const std::vector<Eigen::Vector2d> corners = {{0, 0}, {30, 0}, {30, 10}, {0, 10}};
  PlanarPose truth{0, 0, 0};
  PlanarPose odometry = truth;
  TimestampNs stamp_ns = 0;
  std::vector<std::pair<TimestampNs, double>> held;  // stamps and true headings on side one
  const auto scan_and_move = [&](const PlanarPose& step, double odometry_error_rad, bool blind) {
    truth = Compose(truth, step);
    odometry = Compose(odometry, {step.x_m, step.y_m, step.theta_rad + odometry_error_rad});
    LaserScan scan = test::ScanFrom(walls, truth, 720);
    scan.stamp_ns = stamp_ns += 200'000'000;
    scan.range_max_m = 4;
    for (float& r : scan.ranges_m) {
      if (blind || r > 4) r = std::numeric_limits<float>::infinity();
    }
    pipeline.AddScan(scan, GyroOdometryPose{odometry, true, 0}, Tilt{0, 0});
    return scan.stamp_ns;
  };
  for (int leg = 0; leg < 5; ++leg) {
    const Eigen::Vector2d to = corners[(leg + 1) % corners.size()];
    const bool blind = leg % 2 == 1;
    // Turned on the spot at 0.8 rad/s, blind.
    const double turn =
        WrapAngle(std::atan2(to.y() - truth.y_m, to.x() - truth.x_m) - truth.theta_rad);
    for (int i = 0; i < 10 && leg > 0; ++i) scan_and_move({0, 0, turn / 10}, 0.001, true);
    const double length = leg == 4 ? 6 : std::hypot(to.x() - truth.x_m, to.y() - truth.y_m);
    for (double done = 0; done < length - 1e-9; done += 0.2) {
      const TimestampNs stamp = scan_and_move({std::min(0.2, length - done), 0, 0}, 0, blind);
      if (leg == 0) held.emplace_back(stamp, truth.theta_rad);
    }
  }
  pipeline.Finish();
  EXPECT_GT(pipeline.quality().loops_accepted, 0u);
  double worst = 0;
  for (const auto& [stamp, key_frame] : pipeline.KeyFramePoses()) {
    for (const auto& [held_stamp, heading] : held) {
      if (held_stamp == stamp) {
        worst = std::max(worst, std::abs(WrapAngle(key_frame.theta_rad - heading)));
      }
    }
  }
  return worst;
}

// A loop's correction belongs where the heading was lost: in the blind turns, not along the sides
// the laser and the gyro held together. With the held edges' heading floor as soft as the blind
// odometry's, the loop bends the held side too.
TEST(SlamPipeline, ALoopCorrectsWhereTheLaserDidNotHoldTheHeading) {
  SlamOptions options;
  options.landmarks = false;
  options.alignment_mode = AlignmentMode::kOff;
  const double held = HeldSideHeadingError(options);
  options.gyro_edge_sigma_floor_rad = options.odometry_sigma_rad;
  const double soft = HeldSideHeadingError(options);
  EXPECT_LT(held, 0.004);
  EXPECT_GT(soft, 2 * held);
}

TEST(SlamPipeline, MapRangeBeyondWhatItStoresIsAUsageError) {
  SlamOptions options;
  options.map_max_range_m = 301;
  EXPECT_THROW(SlamPipeline(options, {}), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct

// The SLAM pipeline on synthetic scans: bad input (scans without echoes, time going backwards,
// duplicate stamps, missing odometry) is counted and handled, never a crash.

#include "reconstruct/slam_pipeline.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

LaserScan RoomScan(const PlanarPose& pose, TimestampNs stamp_ns) {
  LaserScan scan = testing::ScanFrom(testing::Room(), pose);
  scan.stamp_ns = stamp_ns;
  return scan;
}

TEST(SlamPipeline, BadScansAndStampsAreCountedNotFatal) {
  SlamPipeline pipeline({}, {});
  const TimestampNs step = 100'000'000;
  PlanarPose truth{2, 2, 0};
  TimestampNs t = step;
  for (int i = 0; i < 10; ++i, t += step) {
    pipeline.AddScan(RoomScan(truth, t), truth);
    truth = Compose(truth, {0.1, 0, 0.01});
  }
  LaserScan nan_scan = RoomScan(truth, t);
  for (float& r : nan_scan.ranges_m) r = std::numeric_limits<float>::quiet_NaN();
  pipeline.AddScan(nan_scan, truth);
  t += step;
  LaserScan max_range = RoomScan(truth, t);
  for (float& r : max_range.ranges_m) r = static_cast<float>(max_range.range_max_m);
  pipeline.AddScan(max_range, std::nullopt);               // and no odometry either
  pipeline.AddScan(RoomScan(truth, t), truth);             // duplicate stamp
  pipeline.AddScan(RoomScan(truth, t - 3 * step), truth);  // back in time
  t += step;
  LaserScan no_beams;
  no_beams.stamp_ns = t;
  pipeline.AddScan(no_beams, truth);  // no beams at all
  t += step;
  pipeline.AddScan(RoomScan(truth, t), truth);
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

}  // namespace
}  // namespace littermap::reconstruct

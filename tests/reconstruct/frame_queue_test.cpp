// Camera frames wait for the odometry reading after them: a frame between two readings gets the
// pose interpolated between them, not the older reading (turning at 1 rad/s with wheels at 50 Hz,
// up to 1.1 degrees off).

#include "reconstruct/frame_queue.hpp"

#include <gtest/gtest.h>

namespace littermap::reconstruct {
namespace {

bag::CompressedRgbd Frame(double t_s) {
  bag::CompressedRgbd frame;
  frame.stamp_ns = FromSeconds(t_s);
  return frame;
}

GyroOdometryPose Turned(double theta_rad) { return {{0, 0, theta_rad}, true, 0}; }

TEST(FrameQueue, AFrameWaitsForTheReadingAfterItAndGetsTheInterpolatedPose) {
  OdometryHistory odometry(0.2);
  FrameQueue queue;
  odometry.Add(FromSeconds(1.00), Turned(0.0));  // turning in place at 1 rad/s
  queue.Push(Frame(1.015));
  EXPECT_TRUE(queue.TakeReady(odometry).empty());  // the reading before it is 15 ms old
  EXPECT_EQ(queue.waiting(), 1u);
  odometry.Add(FromSeconds(1.02), Turned(0.02));
  const std::vector<OdometryFrame> ready = queue.TakeReady(odometry);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].frame.stamp_ns, FromSeconds(1.015));
  ASSERT_TRUE(ready[0].T_odom_base);
  EXPECT_NEAR(ready[0].T_odom_base->theta_rad, 0.015, 1e-9);
  EXPECT_EQ(queue.waiting(), 0u);
}

TEST(FrameQueue, FramesUpToAScanAboutToBeTrackedGoWhateverTheOdometry) {
  OdometryHistory odometry(0.2);
  FrameQueue queue;
  odometry.Add(FromSeconds(1.00), Turned(0.1));
  queue.Push(Frame(1.01));
  queue.Push(Frame(1.05));
  // Odometry overdue: the scan at 1.03 is tracked, and the frame before it goes first with the
  // nearest reading (within the history's age); the later one keeps waiting.
  const std::vector<OdometryFrame> ready = queue.TakeReady(odometry, FromSeconds(1.03));
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].frame.stamp_ns, FromSeconds(1.01));
  ASSERT_TRUE(ready[0].T_odom_base);
  EXPECT_NEAR(ready[0].T_odom_base->theta_rad, 0.1, 1e-12);
  EXPECT_EQ(queue.waiting(), 1u);
}

TEST(FrameQueue, WithoutOdometryAFrameHasNoOdometryPose) {
  OdometryHistory odometry(0.2);
  FrameQueue queue;
  queue.Push(Frame(2.0));
  const std::vector<OdometryFrame> ready = queue.TakeReady(odometry, FromSeconds(2.0));
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_FALSE(ready[0].T_odom_base);
}

}  // namespace
}  // namespace littermap::reconstruct

// Visual odometry (a run without laser) on the real TUM desk pair: the first frame starts the
// trajectory, the second is placed by aligning it; frames without features get no pose, and a
// long run of them starts a new segment.

#include "reconstruct/visual_odometry.hpp"

#include <gtest/gtest.h>

#include "tum_pair.hpp"

namespace littermap::reconstruct {
namespace {

TEST(VisualOdometry, PlacesTheSecondFrameOfTheTumPairByItsAlignment) {
  const TumPair pair = LoadTumPair();
  ASSERT_FALSE(pair.first.colour_bgr.empty()) << "tum_pair data set missing";
  VisualOdometry odometry({}, pair.camera);
  const VisualOdometryStep first = odometry.Track(pair.first);
  EXPECT_TRUE(first.tracked && first.new_segment && first.new_key_frame);
  EXPECT_TRUE(first.T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  const VisualOdometryStep second = odometry.Track(pair.second);
  ASSERT_TRUE(second.tracked);
  EXPECT_FALSE(second.new_segment);
  const RgbdAlignment direct = RgbdAligner().Align(pair.first, pair.second, pair.camera);
  EXPECT_TRUE(second.T_world_camera.isApprox(direct.T_keyframe_frame, 1e-9));
  // 14 cm apart: more than a key frame's spacing.
  EXPECT_TRUE(second.new_key_frame);
  EXPECT_EQ(odometry.stats().key_frames, 2u);
}

TEST(VisualOdometry, FramesWithoutFeaturesAreLostThenANewSegmentStarts) {
  const TumPair pair = LoadTumPair();
  ASSERT_FALSE(pair.first.colour_bgr.empty()) << "tum_pair data set missing";
  VisualOdometryOptions options;
  options.max_lost_frames = 3;
  VisualOdometry odometry(options, pair.camera);
  odometry.Track(pair.first);
  const Eigen::Isometry3d T_world_second = odometry.Track(pair.second).T_world_camera;
  RgbdImage blank = pair.first;
  blank.colour_bgr.setTo(cv::Scalar(128, 128, 128));
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(odometry.Track(blank).tracked);
  // Lost three times in a row: the next frame starts a segment at the last pose known.
  const VisualOdometryStep restart = odometry.Track(pair.first);
  EXPECT_TRUE(restart.tracked && restart.new_segment);
  EXPECT_TRUE(restart.T_world_camera.isApprox(T_world_second));
  EXPECT_EQ(odometry.stats().segments, 2u);
  EXPECT_EQ(odometry.stats().frames, 6u);
  EXPECT_EQ(odometry.stats().tracked, 3u);
}

}  // namespace
}  // namespace littermap::reconstruct

// Routine 3's RGB-D tracker on the real TUM desk pair: key frames taken while the laser tracks,
// anchored to the 2D key frames (they follow the pose graph), and the base pose of a later frame
// from aligning it to them.

#include "reconstruct/rgbd_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "core/pose3.hpp"
#include "tum_pair.hpp"

namespace littermap::reconstruct {
namespace {

constexpr TimestampNs kStamp1 = 1'000'000'000, kStamp2 = 1'100'000'000;

// The camera 0.2 m ahead of base_link and 0.5 m up, looking forward (optical z = base x).
Eigen::Isometry3d BaseCamera() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  T.translation() = Eigen::Vector3d(0.2, 0, 0.5);
  return T;
}

bag::CompressedRgbd Compress(const RgbdImage& image, TimestampNs stamp_ns) {
  cv::Mat depth_mm;  // TUM depth is in 1/5000 m
  image.depth.convertTo(depth_mm, CV_16U, image.depth_unit_m * 1000);
  const msg::Header header = bag::MakeHeader(stamp_ns, "camera");
  return {stamp_ns, bag::EncodeColorJpeg(image.colour_bgr, header),
          bag::EncodeDepthPng(depth_mm, header), "colour", "depth"};
}

RgbdImage Decode(const bag::CompressedRgbd& frame) {
  return {bag::DecodeColor(frame.colour), bag::DecodeDepthMm(frame.depth), 0.001};
}

class RgbdTrackerTest : public testing::Test {
 protected:
  void SetUp() override {
    const TumPair pair = LoadTumPair();
    ASSERT_FALSE(pair.first.colour_bgr.empty()) << "tum_pair data set missing";
    camera_ = pair.camera;
    frame1_ = Compress(pair.first, kStamp1);
    frame2_ = Compress(pair.second, kStamp2);
    map_.Add({0, kStamp1, kKeyFramePose, {{1, 0}, {1, 1}, {1, -1}, {2, 0}}, 0, {}});
  }

  // Frame 1 tracked by the laser at the key frame's pose.
  void TrackFirstByLaser(RgbdTracker* tracker) {
    tracker->AddFrame(frame1_, std::nullopt);
    TrackStep step;
    step.routine = Routine::kGlobal;
    step.T_world_base = kKeyFramePose;
    tracker->OnTracked({kStamp1, {}, std::nullopt, std::nullopt}, step, map_);
  }

  // The base pose of frame 2 that the alignment of the two images implies.
  PlanarPose Expected(const PlanarPose& T_world_keyframe) const {
    const RgbdAlignment alignment = RgbdAligner().Align(Decode(frame1_), Decode(frame2_), camera_);
    EXPECT_TRUE(alignment.ok);
    return ToPlanar(LiftPose(T_world_keyframe, std::nullopt) * BaseCamera() *
                    alignment.T_keyframe_frame * BaseCamera().inverse());
  }

  const PlanarPose kKeyFramePose{3, -2, 0.4};
  RgbdCameraModel camera_;
  bag::CompressedRgbd frame1_, frame2_;
  KeyFrameMap map_{KeyFrameMapOptions{}, IcpOptions{}};
};

void ExpectNear(const PlanarPose& actual, const PlanarPose& expected) {
  EXPECT_NEAR(actual.x_m, expected.x_m, 1e-3);
  EXPECT_NEAR(actual.y_m, expected.y_m, 1e-3);
  EXPECT_NEAR(WrapAngle(actual.theta_rad - expected.theta_rad), 0, 1e-3);
}

TEST_F(RgbdTrackerTest, PlacesAFrameByAligningItToTheKeyFrameTheLaserTracked) {
  RgbdTracker tracker({}, camera_, BaseCamera());
  TrackFirstByLaser(&tracker);
  EXPECT_EQ(tracker.stats().key_frames, 1u);
  tracker.AddFrame(frame2_, std::nullopt);
  const auto pose = tracker.AlignAt({kStamp2, {}, std::nullopt, std::nullopt}, kKeyFramePose, map_);
  ASSERT_TRUE(pose);
  const PlanarPose expected = Expected(kKeyFramePose);
  ExpectNear(*pose, expected);
  // The desk pair moved 14 cm: the pose is neither the key frame's nor far from it.
  const double moved_m = std::hypot(pose->x_m - kKeyFramePose.x_m, pose->y_m - kKeyFramePose.y_m);
  EXPECT_GT(moved_m, 0.03);
  EXPECT_LT(moved_m, 0.3);
  EXPECT_EQ(tracker.stats().aligned, 1u);
}

TEST_F(RgbdTrackerTest, KeyFramesFollowTheirLaserKeyFrameWhenThePoseGraphMovesIt) {
  RgbdTracker tracker({}, camera_, BaseCamera());
  TrackFirstByLaser(&tracker);
  const PlanarPose moved{5, 1, -1.0};
  map_.SetPoses({moved});
  tracker.AddFrame(frame2_, std::nullopt);
  const auto pose = tracker.AlignAt({kStamp2, {}, std::nullopt, std::nullopt}, moved, map_);
  ASSERT_TRUE(pose);
  ExpectNear(*pose, Expected(moved));
}

TEST_F(RgbdTrackerTest, NoPoseWithoutAKeyFrameOrACurrentFrame) {
  RgbdTracker tracker({}, camera_, BaseCamera());
  tracker.AddFrame(frame2_, std::nullopt);
  EXPECT_FALSE(tracker.AlignAt({kStamp2, {}, std::nullopt, std::nullopt}, kKeyFramePose, map_));
  RgbdTracker other({}, camera_, BaseCamera());
  TrackFirstByLaser(&other);
  other.AddFrame(frame2_, std::nullopt);
  // A scan 1 s after the latest frame: the frame does not show the scan's pose.
  EXPECT_FALSE(other.AlignAt({kStamp2 + 1'000'000'000, {}, std::nullopt, std::nullopt},
                             kKeyFramePose, map_));
}

// After a 20 m drive the robot is back at the desk, its tracked pose 0.3 m and 2 degrees off
// (drift): the camera frame matches the RGB-D key frame of the first visit, and the loop puts the
// base where the alignment says, relative to that key frame.
TEST_F(RgbdTrackerTest, AFrameThatMatchesAKeyFrameFromFarBackAlongThePathIsALoop) {
  RgbdTracker tracker({}, camera_, BaseCamera());
  TrackFirstByLaser(&tracker);
  const PlanarPose drifted{kKeyFramePose.x_m + 0.2, kKeyFramePose.y_m - 0.22,
                           kKeyFramePose.theta_rad + 0.035};
  map_.Add({1, kStamp2, drifted, {{1, 0}, {1, 1}, {1, -1}, {2, 0}}, 20.0, {}});
  tracker.AddFrame(frame2_, std::nullopt);
  TrackStep step;
  step.routine = Routine::kGlobal;
  step.T_world_base = drifted;
  step.key_frame = 1;
  step.new_key_frame = true;
  const TrackInput input{kStamp2, {}, std::nullopt, std::nullopt};
  const auto loop = tracker.FindLoop(input, step, map_);
  ASSERT_TRUE(loop);
  EXPECT_EQ(loop->key_frame, 0u);
  EXPECT_GE(loop->confidence, 0.5);
  ExpectNear(loop->T_world_base, Expected(kKeyFramePose));
  EXPECT_EQ(tracker.stats().loop_alignments, 1u);

  // The same frames 5 m of path apart are the robot passing by, not a loop ...
  RgbdTracker near({}, camera_, BaseCamera());
  KeyFrameMap short_path{KeyFrameMapOptions{}, IcpOptions{}};
  short_path.Add({0, kStamp1, kKeyFramePose, {{1, 0}, {1, 1}, {1, -1}, {2, 0}}, 0, {}});
  near.AddFrame(frame1_, std::nullopt);
  TrackStep first;
  first.routine = Routine::kGlobal;
  first.T_world_base = kKeyFramePose;
  near.OnTracked({kStamp1, {}, std::nullopt, std::nullopt}, first, short_path);
  short_path.Add({1, kStamp2, drifted, {{1, 0}, {1, 1}, {1, -1}, {2, 0}}, 5.0, {}});
  near.AddFrame(frame2_, std::nullopt);
  EXPECT_FALSE(near.FindLoop(input, step, short_path));
  // ... and with the drift beyond what 20 m of path allows (1 m + 3 %), nothing is tried.
  const PlanarPose far{kKeyFramePose.x_m + 2.5, kKeyFramePose.y_m, kKeyFramePose.theta_rad};
  step.T_world_base = far;
  map_.SetPoses({kKeyFramePose, far});
  EXPECT_FALSE(tracker.FindLoop(input, step, map_));
  EXPECT_EQ(tracker.stats().loop_alignments, 1u);
}

TEST_F(RgbdTrackerTest, FramesThePoseOfWhichNothingMeasuredMakeNoKeyFrames) {
  RgbdTracker tracker({}, camera_, BaseCamera());
  tracker.AddFrame(frame1_, std::nullopt);
  TrackStep step;
  step.routine = Routine::kOdometryOnly;
  step.T_world_base = kKeyFramePose;
  const Tilt tilt{0.1, -0.05};
  tracker.OnTracked({kStamp1, {}, std::nullopt, tilt}, step, map_);
  EXPECT_EQ(tracker.stats().key_frames, 0u);
  ASSERT_EQ(tracker.camera_poses().size(), 1u);
  const CameraPose& pose = tracker.camera_poses()[0];
  EXPECT_EQ(pose.source, CameraPoseSource::kOdometry);
  // Its 3D pose carries the tilt: the base's roll and pitch, the camera's mount.
  const Eigen::Isometry3d expected = LiftPose({0, 0, 0}, tilt) * BaseCamera();
  EXPECT_TRUE(pose.T_scan_camera.isApprox(expected, 1e-9));
}

}  // namespace
}  // namespace littermap::reconstruct

#pragma once
// The RGB-D frames of a run bag: colour (JPEG) and depth (16-bit PNG, mm) paired by stamp, with
// the camera intrinsics, the base_link -> optical frame extrinsic from /tf_static and the
// robot's roll and pitch from the IMU at each frame (to level the cloud).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "bag/header_stamps.hpp"
#include "bag/topics.hpp"
#include "core/pose3.hpp"
#include "core/time.hpp"
#include "detect/camera_intrinsics.hpp"

namespace littermap::detect {

struct RgbdFrameOptions {
  bag::RunTopics topics;  // colour, depth, camera info, tf_static, imu, camera frame
  bag::StampSource stamps = bag::StampSource::kHeader;  // bag/header_stamps.hpp
  double max_pair_gap_s = 0.02;  // colour and depth of one frame, stamp difference
  double max_imu_age_s = 0.1;    // older tilt counts as unknown (the cloud is then not levelled)
};

struct RgbdFrame {
  std::size_t index = 0;  // 0-based position of the colour image on its topic
  TimestampNs stamp_ns = 0;
  cv::Mat colour_bgr;
  cv::Mat depth_mm;
  std::optional<RollPitchYaw> tilt;  // roll and pitch of base_link (yaw 0)
};

class RgbdFrameReader {
 public:
  // Reads the camera info and the extrinsic. Throws BadInputError naming the bag and topic when
  // the colour, depth or camera-info topic or the camera transform is missing.
  RgbdFrameReader(std::filesystem::path bag, RgbdFrameOptions options);

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const Eigen::Isometry3d& T_base_camera() const { return T_base_camera_; }
  std::uint64_t colour_count() const { return colour_count_; }

  // Decodes and visits every `every`-th frame (index % every == 0) in time order. A colour image
  // without a depth image within max_pair_gap_s is skipped. Throws BadInputError naming the bag,
  // topic and message index for a message that does not decode.
  void ForEach(std::size_t every, const std::function<void(const RgbdFrame&)>& visit) const;

 private:
  std::filesystem::path bag_;
  RgbdFrameOptions options_;
  CameraIntrinsics intrinsics_;
  Eigen::Isometry3d T_base_camera_ = Eigen::Isometry3d::Identity();
  std::uint64_t colour_count_ = 0;
};

// T_level_camera: the optical frame in the levelled base frame (base_link rotated by the tilt).
Eigen::Isometry3f LevelledCamera(const Eigen::Isometry3d& T_base_camera,
                                 const std::optional<RollPitchYaw>& tilt);

}  // namespace littermap::detect

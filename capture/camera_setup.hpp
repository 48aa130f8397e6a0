#pragma once
// The RGB-D camera of a run bag: its CameraInfo (the first on the topic) and the base_link ->
// optical frame extrinsic from /tf_static (a camera-only bag, such as an imported TUM sequence,
// may have none).

#include <filesystem>
#include <string>

#include <Eigen/Geometry>

#include "capture/ros_messages.hpp"
#include "capture/topics.hpp"

namespace littermap {

struct CameraSetupTopics {
  std::string camera_info = topics::kCameraInfo;
  std::string tf_static = topics::kTfStatic;
  std::string camera_frame = frames::kCamera;
};

struct CameraSetup {
  msg::CameraInfo info;
  Eigen::Isometry3d T_base_camera = Eigen::Isometry3d::Identity();
};

enum class Extrinsic { kRequired, kOptional };  // kOptional: identity when the bag has none

// Throws BadInputError naming the bag and topic when the camera info or a required extrinsic is
// missing.
CameraSetup ReadCameraSetup(const std::filesystem::path& bag, const CameraSetupTopics& topics,
                            Extrinsic extrinsic = Extrinsic::kRequired);

}  // namespace littermap

#pragma once
// The RGB-D camera of a run bag: its CameraInfo (the first on the topic) and the base_link ->
// optical frame extrinsic from the fixed transforms on /tf_static and /tf
// (bag/transform_tree.hpp), for the configured optical frame or else the one the camera info
// names (a camera-only bag, such as an imported TUM sequence, may have none).

#include <filesystem>
#include <string>

#include <Eigen/Geometry>

#include "bag/ros_messages.hpp"
#include "bag/topics.hpp"

namespace littermap::bag {

struct CameraSetup {
  msg::CameraInfo info;
  Eigen::Isometry3d T_base_camera = Eigen::Isometry3d::Identity();
};

enum class Extrinsic { kRequired, kOptional };  // kOptional: identity when the bag has none

// Throws BadInputError naming the bag and topic when the camera info or a required extrinsic is
// missing.
CameraSetup ReadCameraSetup(const std::filesystem::path& bag, const RunTopics& topics,
                            Extrinsic extrinsic = Extrinsic::kRequired);

}  // namespace littermap::bag

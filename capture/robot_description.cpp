#include "capture/robot_description.hpp"

#include <yaml-cpp/yaml.h>

#include "bag/sensor_messages.hpp"
#include "bag/topics.hpp"
#include "core/error.hpp"
#include "core/mount.hpp"
#include "core/yaml_fields.hpp"

namespace littermap::capture {
namespace {

Eigen::Isometry3d ReadSensorMount(YamlFields& robot, const char* sensor) {
  YamlFields fields = robot.Child(sensor);
  MountSpec mount;
  ReadMount(fields.Child("mount"), mount);
  fields.Finish();
  return MountPose(mount);
}

}  // namespace

RobotDescription ReadRobotDescription(const std::filesystem::path& path) {
  const YAML::Node root = LoadYamlFile(path);
  if (!root.IsMap())
    throw BadInputError(path.string() + ": the robot description is not a mapping");
  YamlFields robot(root, path, "");
  RobotDescription out;
  out.T_base_laser = ReadSensorMount(robot, "laser");
  out.T_base_optical = ReadSensorMount(robot, "camera") * T_body_optical();
  robot.Finish();
  return out;
}

msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const RobotDescription& robot) {
  return bag::sensor_messages::StaticTransforms(stamp_ns, robot.T_base_laser, robot.T_base_optical);
}

}  // namespace littermap::capture

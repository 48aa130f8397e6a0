#include "capture/robot_description.hpp"

#include <yaml-cpp/yaml.h>

#include "capture/sensor_messages.hpp"
#include "capture/topics.hpp"
#include "core/error.hpp"
#include "sim/camera_model.hpp"
#include "sim/simulation.hpp"
#include "sim/world_spec.hpp"
#include "sim/yaml_fields.hpp"

namespace littermap {
namespace {

Eigen::Isometry3d ReadSensorMount(sim::YamlFields& robot, const char* sensor) {
  sim::YamlFields fields = robot.Child(sensor);
  sim::MountSpec mount;
  sim::ReadMount(fields.Child("mount"), mount);
  fields.Finish();
  return sim::MountPose(mount);
}

}  // namespace

RobotDescription ReadRobotDescription(const std::filesystem::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
  } catch (const YAML::BadFile&) {
    throw BadInputError(path.string() + ": cannot read the robot description");
  } catch (const YAML::Exception& error) {
    throw BadInputError(path.string() + ": not valid YAML: " + error.what());
  }
  if (!root.IsMap())
    throw BadInputError(path.string() + ": the robot description is not a mapping");
  sim::YamlFields robot(root, path, "");
  RobotDescription out;
  out.T_base_laser = ReadSensorMount(robot, "laser");
  out.T_base_optical = ReadSensorMount(robot, "camera") * sim::T_body_optical();
  robot.Finish();
  return out;
}

msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const RobotDescription& robot) {
  return msg::TFMessage{
      {sensor_messages::TransformFromBase(stamp_ns, frames::kLaser, robot.T_base_laser),
       sensor_messages::TransformFromBase(stamp_ns, frames::kCamera, robot.T_base_optical)}};
}

}  // namespace littermap

#include "core/mount.hpp"

#include <numbers>

#include "core/pose3.hpp"

namespace littermap {

void ReadMount(YamlFields fields, MountSpec& mount) {
  fields.Read("x_m", mount.x_m);
  fields.Read("y_m", mount.y_m);
  fields.Read("z_m", mount.z_m);
  fields.Read("roll_deg", mount.roll_deg);
  fields.Read("pitch_deg", mount.pitch_deg);
  fields.Read("yaw_deg", mount.yaw_deg);
  fields.Finish();
}

Eigen::Isometry3d MountPose(const MountSpec& mount) {
  constexpr double kDegToRad = std::numbers::pi / 180;
  return MakeIsometry(
      {mount.x_m, mount.y_m, mount.z_m},
      {mount.roll_deg * kDegToRad, mount.pitch_deg * kDegToRad, mount.yaw_deg * kDegToRad});
}

}  // namespace littermap

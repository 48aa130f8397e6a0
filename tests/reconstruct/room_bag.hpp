#pragma once
// The scans of the known room (support/room_run.hpp) recorded as a run bag: /scan and, unless
// left out, the laser's extrinsic on /tf_static; and the room's trajectories as TUM files.

#include <filesystem>

#include <Eigen/Geometry>

#include "bag/bag_writer.hpp"
#include "bag/sensor_messages.hpp"
#include "bag/topics.hpp"
#include "support/room_run.hpp"

namespace littermap::test {

inline void WriteRoomBag(const std::filesystem::path& bag, const RoomScans& run,
                         bool with_extrinsic = true) {
  bag::BagWriter writer(bag);
  writer.AddTopic<msg::LaserScan>(topics::kScan);
  if (with_extrinsic) {
    writer.AddTopic<msg::TFMessage>(topics::kTfStatic, bag::TopicQos::kLatched);
    Eigen::Isometry3d T_base_laser = Eigen::Isometry3d::Identity();
    T_base_laser.translation() = Eigen::Vector3d(kBaseLaser.x_m, kBaseLaser.y_m, 0.3);
    T_base_laser.linear() =
        Eigen::AngleAxisd(kBaseLaser.theta_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    writer.WriteMessage(
        topics::kTfStatic, run.scans.front().stamp_ns,
        bag::sensor_messages::StaticTransforms(run.scans.front().stamp_ns, T_base_laser,
                                               Eigen::Isometry3d::Identity()));
  }
  for (const LaserScan& scan : run.scans) {
    writer.WriteMessage(topics::kScan, scan.stamp_ns,
                        bag::sensor_messages::Scan(scan.stamp_ns, scan));
  }
  writer.Close();
}

}  // namespace littermap::test

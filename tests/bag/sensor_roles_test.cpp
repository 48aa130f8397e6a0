// Sensor roles: littermap's own names, a real robot's names found by type, a choice the user
// must make, and the errors for a wrong choice.

#include <gtest/gtest.h>

#include "bag/sensor_roles.hpp"
#include "support/expect_bad_input.hpp"

namespace littermap::bag {
namespace {

BagInfo Bag(const std::vector<std::pair<std::string, std::string>>& topics) {
  BagInfo info;
  for (const auto& [name, type] : topics) {
    TopicInfo topic;
    topic.name = name;
    topic.type = type;
    info.topics.push_back(topic);
  }
  return info;
}

TEST(SensorRoles, DefaultNamesFirst) {
  const BagInfo info = Bag({{"/scan", "sensor_msgs/msg/LaserScan"},
                            {"/odom", "nav_msgs/msg/Odometry"},
                            {"/odometry/filtered", "nav_msgs/msg/Odometry"},
                            {"/camera/color/camera_info", "sensor_msgs/msg/CameraInfo"},
                            {"/camera/depth/camera_info", "sensor_msgs/msg/CameraInfo"}});
  const SensorRoles roles = ResolveSensorRoles(info);
  EXPECT_EQ(roles.topics.scan, "/scan");
  EXPECT_EQ(roles.found.at("scan"), "default");
  EXPECT_EQ(roles.topics.odometry, "/odom") << "two odometry topics, one with the default name";
  EXPECT_EQ(roles.topics.camera_info, "/camera/color/camera_info");
  EXPECT_EQ(roles.found.at("imu"), "missing");
}

TEST(SensorRoles, ARealRobotsTopicsByType) {
  const BagInfo info =
      Bag({{"/scan_front", "sensor_msgs/msg/LaserScan"},
           {"/odometry/filtered", "nav_msgs/msg/Odometry"},
           {"/imu_data", "sensor_msgs/msg/Imu"},
           {"/camera/camera/color/image_raw", "sensor_msgs/msg/Image"},
           {"/camera/camera/color/camera_info", "sensor_msgs/msg/CameraInfo"},
           {"/camera/camera/aligned_depth_to_color/image_raw", "sensor_msgs/msg/Image"},
           {"/camera/camera/aligned_depth_to_color/camera_info", "sensor_msgs/msg/CameraInfo"},
           {"/tf", "tf2_msgs/msg/TFMessage"}});
  const SensorRoles roles = ResolveSensorRoles(info);
  EXPECT_EQ(roles.topics.scan, "/scan_front");
  EXPECT_EQ(roles.topics.odometry, "/odometry/filtered");
  EXPECT_EQ(roles.topics.imu, "/imu_data");
  EXPECT_EQ(roles.topics.colour, "/camera/camera/color/image_raw");
  EXPECT_EQ(roles.topics.depth, "/camera/camera/aligned_depth_to_color/image_raw");
  EXPECT_EQ(roles.topics.camera_info, "/camera/camera/color/camera_info");
  for (const auto& role : SensorRoleNames()) EXPECT_EQ(roles.found.at(role), "by type") << role;
}

TEST(SensorRoles, TwoLasersNeedAChoice) {
  const BagInfo info = Bag(
      {{"/scan_front", "sensor_msgs/msg/LaserScan"}, {"/scan_rear", "sensor_msgs/msg/LaserScan"}});
  test::ExpectBadInput([&] { ResolveSensorRoles(info); },
                       "2 scan topics (/scan_front, /scan_rear): choose one with --topic "
                       "scan=TOPIC");
  const auto given = ParseRoleAssignments({"scan=/scan_rear"});
  const SensorRoles roles = ResolveSensorRoles(info, given);
  EXPECT_EQ(roles.topics.scan, "/scan_rear");
  EXPECT_EQ(roles.found.at("scan"), "given");
}

TEST(SensorRoles, InfoShowsAnAmbiguousRoleInsteadOfStopping) {
  const BagInfo info = Bag({{"/scan_front", "sensor_msgs/msg/LaserScan"},
                            {"/scan_rear", "sensor_msgs/msg/LaserScan"},
                            {"/odometry/filtered", "nav_msgs/msg/Odometry"}});
  const SensorRoles roles = FindSensorRoles(info);
  EXPECT_EQ(roles.found.at("scan"), "ambiguous");
  EXPECT_EQ(roles.candidates.at("scan"), (std::vector<std::string>{"/scan_front", "/scan_rear"}));
  EXPECT_EQ(TopicOf(roles, "odometry"), "/odometry/filtered");
  const std::vector<std::string> lines = DescribeSensorRoles(roles);
  ASSERT_EQ(lines.size(), SensorRoleNames().size());
  EXPECT_EQ(lines[0], "scan: one of /scan_front, /scan_rear (--topic scan=TOPIC)");
  EXPECT_EQ(lines[1], "odometry: /odometry/filtered (by type)");
  EXPECT_EQ(lines[2], "imu: none");
  EXPECT_THROW(TopicOf(roles, "lidar"), UsageError);
}

// A topic with the role's default name but another type is not read as the role's (an IMU read
// as laser scans decoded to nothing and reconstructed zero poses without a word).
TEST(SensorRoles, ADefaultNameOfAnotherTypeIsBadInput) {
  const BagInfo info = Bag({{"/scan", "sensor_msgs/msg/Imu"}, {"/odom", "nav_msgs/msg/Odometry"}});
  test::ExpectBadInput([&] { ResolveSensorRoles(info); },
                       "topic '/scan' has type sensor_msgs/msg/Imu, not sensor_msgs/msg/LaserScan: "
                       "name the scan topic with --topic scan=TOPIC");
  EXPECT_EQ(FindSensorRoles(info).found.at("scan"), "missing") << "info shows it, not stops";
}

TEST(SensorRoles, WrongChoicesAreUsageErrors) {
  const BagInfo info =
      Bag({{"/scan_front", "sensor_msgs/msg/LaserScan"}, {"/odom", "nav_msgs/msg/Odometry"}});
  EXPECT_THROW(ParseRoleAssignments({"lidar=/scan_front"}), UsageError);
  EXPECT_THROW(ParseRoleAssignments({"scan"}), UsageError);
  EXPECT_THROW(ResolveSensorRoles(info, {{"scan", "/nope"}}), UsageError);
  EXPECT_THROW(ResolveSensorRoles(info, {{"scan", "/odom"}}), UsageError);
}

}  // namespace
}  // namespace littermap::bag

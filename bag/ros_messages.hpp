#pragma once
// Plain C++ mirrors of the ROS 2 message types a run bag carries. Field names and order follow
// the .msg definitions exactly (common_interfaces, rolling), because the CDR layout is the field
// order. Fixed-size ROS arrays are std::array, unbounded sequences std::vector.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace littermap::msg {

// builtin_interfaces/msg/Time
struct Time {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  bool operator==(const Time&) const = default;
};

// std_msgs/msg/Header
struct Header {
  Time stamp;
  std::string frame_id;
  bool operator==(const Header&) const = default;
};

// std_msgs/msg/String
struct String {
  std::string data;
  bool operator==(const String&) const = default;
};

// geometry_msgs/msg/Vector3
struct Vector3 {
  double x = 0, y = 0, z = 0;
  bool operator==(const Vector3&) const = default;
};

// geometry_msgs/msg/Point
struct Point {
  double x = 0, y = 0, z = 0;
  bool operator==(const Point&) const = default;
};

// geometry_msgs/msg/Quaternion
struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
  bool operator==(const Quaternion&) const = default;
};

// geometry_msgs/msg/Pose
struct Pose {
  Point position;
  Quaternion orientation;
  bool operator==(const Pose&) const = default;
};

// geometry_msgs/msg/PoseWithCovariance
struct PoseWithCovariance {
  Pose pose;
  std::array<double, 36> covariance{};
  bool operator==(const PoseWithCovariance&) const = default;
};

// geometry_msgs/msg/Twist
struct Twist {
  Vector3 linear;
  Vector3 angular;
  bool operator==(const Twist&) const = default;
};

// geometry_msgs/msg/TwistWithCovariance
struct TwistWithCovariance {
  Twist twist;
  std::array<double, 36> covariance{};
  bool operator==(const TwistWithCovariance&) const = default;
};

// geometry_msgs/msg/Transform
struct Transform {
  Vector3 translation;
  Quaternion rotation;
  bool operator==(const Transform&) const = default;
};

// geometry_msgs/msg/TransformStamped
struct TransformStamped {
  Header header;
  std::string child_frame_id;
  Transform transform;
  bool operator==(const TransformStamped&) const = default;
};

// tf2_msgs/msg/TFMessage
struct TFMessage {
  std::vector<TransformStamped> transforms;
  bool operator==(const TFMessage&) const = default;
};

// sensor_msgs/msg/LaserScan
struct LaserScan {
  Header header;
  float angle_min = 0;        // rad
  float angle_max = 0;        // rad
  float angle_increment = 0;  // rad
  float time_increment = 0;   // s between measurements
  float scan_time = 0;        // s between scans
  float range_min = 0;        // m
  float range_max = 0;        // m
  std::vector<float> ranges;  // m
  std::vector<float> intensities;
  bool operator==(const LaserScan&) const = default;
};

// sensor_msgs/msg/Image
struct Image {
  Header header;
  std::uint32_t height = 0;
  std::uint32_t width = 0;
  std::string encoding;
  std::uint8_t is_bigendian = 0;
  std::uint32_t step = 0;
  std::vector<std::uint8_t> data;
  bool operator==(const Image&) const = default;
};

// sensor_msgs/msg/CompressedImage
struct CompressedImage {
  Header header;
  std::string format;
  std::vector<std::uint8_t> data;
  bool operator==(const CompressedImage&) const = default;
};

// sensor_msgs/msg/RegionOfInterest
struct RegionOfInterest {
  std::uint32_t x_offset = 0;
  std::uint32_t y_offset = 0;
  std::uint32_t height = 0;
  std::uint32_t width = 0;
  bool do_rectify = false;
  bool operator==(const RegionOfInterest&) const = default;
};

// sensor_msgs/msg/CameraInfo
struct CameraInfo {
  Header header;
  std::uint32_t height = 0;
  std::uint32_t width = 0;
  std::string distortion_model;
  std::vector<double> d;
  std::array<double, 9> k{};
  std::array<double, 9> r{};
  std::array<double, 12> p{};
  std::uint32_t binning_x = 0;
  std::uint32_t binning_y = 0;
  RegionOfInterest roi;
  bool operator==(const CameraInfo&) const = default;
};

// sensor_msgs/msg/Imu
struct Imu {
  Header header;
  Quaternion orientation;
  std::array<double, 9> orientation_covariance{};
  Vector3 angular_velocity;
  std::array<double, 9> angular_velocity_covariance{};
  Vector3 linear_acceleration;
  std::array<double, 9> linear_acceleration_covariance{};
  bool operator==(const Imu&) const = default;
};

// sensor_msgs/msg/NavSatStatus
struct NavSatStatus {
  std::int8_t status = 0;
  std::uint16_t service = 0;
  bool operator==(const NavSatStatus&) const = default;
};

// sensor_msgs/msg/NavSatFix
struct NavSatFix {
  Header header;
  NavSatStatus status;
  double latitude = 0;
  double longitude = 0;
  double altitude = 0;
  std::array<double, 9> position_covariance{};
  std::uint8_t position_covariance_type = 0;
  bool operator==(const NavSatFix&) const = default;
};

// nav_msgs/msg/Odometry
struct Odometry {
  Header header;
  std::string child_frame_id;
  PoseWithCovariance pose;
  TwistWithCovariance twist;
  bool operator==(const Odometry&) const = default;
};

}  // namespace littermap::msg

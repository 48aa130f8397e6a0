#pragma once
// CDR encode/decode of the ROS 2 message types in ros_messages.hpp, plus each type's ROS name
// ("sensor_msgs/msg/LaserScan") and .msg definition text (stored in the bag so that tools such
// as Foxglove can decode the messages without the ROS packages installed).
//
//   std::vector<uint8_t> bytes = Encode(scan);
//   msg::LaserScan scan = Decode<msg::LaserScan>(bytes);   // throws cdr::CdrError

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "bag/cdr.hpp"
#include "bag/ros_messages.hpp"

namespace littermap::bag {

// MessageTraits<M>::kTypeName is the ROS 2 type name; Definition() the ros2msg definition with
// its dependencies appended in rosbag2's "=====\nMSG: pkg/Type\n" layout.
template <typename M>
struct MessageTraits;

#define LITTERMAP_DECLARE_MESSAGE(Type, ros_name)               \
  template <>                                                   \
  struct MessageTraits<msg::Type> {                             \
    static constexpr std::string_view kTypeName = ros_name;     \
    static std::string_view Definition();                       \
  };                                                            \
  void EncodeInto(cdr::Writer& writer, const msg::Type& value); \
  void DecodeFrom(cdr::Reader& reader, msg::Type& value);

LITTERMAP_DECLARE_MESSAGE(Time, "builtin_interfaces/msg/Time")
LITTERMAP_DECLARE_MESSAGE(Header, "std_msgs/msg/Header")
LITTERMAP_DECLARE_MESSAGE(String, "std_msgs/msg/String")
LITTERMAP_DECLARE_MESSAGE(Vector3, "geometry_msgs/msg/Vector3")
LITTERMAP_DECLARE_MESSAGE(Point, "geometry_msgs/msg/Point")
LITTERMAP_DECLARE_MESSAGE(Quaternion, "geometry_msgs/msg/Quaternion")
LITTERMAP_DECLARE_MESSAGE(Pose, "geometry_msgs/msg/Pose")
LITTERMAP_DECLARE_MESSAGE(PoseWithCovariance, "geometry_msgs/msg/PoseWithCovariance")
LITTERMAP_DECLARE_MESSAGE(Twist, "geometry_msgs/msg/Twist")
LITTERMAP_DECLARE_MESSAGE(TwistWithCovariance, "geometry_msgs/msg/TwistWithCovariance")
LITTERMAP_DECLARE_MESSAGE(Transform, "geometry_msgs/msg/Transform")
LITTERMAP_DECLARE_MESSAGE(TransformStamped, "geometry_msgs/msg/TransformStamped")
LITTERMAP_DECLARE_MESSAGE(TFMessage, "tf2_msgs/msg/TFMessage")
LITTERMAP_DECLARE_MESSAGE(LaserScan, "sensor_msgs/msg/LaserScan")
LITTERMAP_DECLARE_MESSAGE(Image, "sensor_msgs/msg/Image")
LITTERMAP_DECLARE_MESSAGE(CompressedImage, "sensor_msgs/msg/CompressedImage")
LITTERMAP_DECLARE_MESSAGE(RegionOfInterest, "sensor_msgs/msg/RegionOfInterest")
LITTERMAP_DECLARE_MESSAGE(CameraInfo, "sensor_msgs/msg/CameraInfo")
LITTERMAP_DECLARE_MESSAGE(Imu, "sensor_msgs/msg/Imu")
LITTERMAP_DECLARE_MESSAGE(NavSatStatus, "sensor_msgs/msg/NavSatStatus")
LITTERMAP_DECLARE_MESSAGE(NavSatFix, "sensor_msgs/msg/NavSatFix")
LITTERMAP_DECLARE_MESSAGE(Odometry, "nav_msgs/msg/Odometry")

#undef LITTERMAP_DECLARE_MESSAGE

template <typename M>
std::vector<std::uint8_t> Encode(const M& message) {
  cdr::Writer writer;
  EncodeInto(writer, message);
  return writer.Take();
}

// Decodes one whole message. Trailing bytes after the last field are allowed (DDS pads
// serialized payloads to a multiple of 4); a message shorter than its fields throws.
template <typename M>
M Decode(std::span<const std::uint8_t> bytes) {
  cdr::Reader reader(bytes);
  M message;
  DecodeFrom(reader, message);
  return message;
}

}  // namespace littermap::bag

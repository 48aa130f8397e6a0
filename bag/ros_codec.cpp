#include "bag/ros_codec.hpp"

#include <array>
#include <concepts>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

// The CDR layout of a ROS 2 message is its .msg field order with nested messages inlined (XCDR1
// FINAL types have no per-struct header or alignment). Each message type below lists its fields
// once, in .msg declaration order, in a `Fields` function; encoding, decoding and the minimum
// encoded size are visitors over that one list, so they cannot disagree on the order. The .msg
// texts themselves are in message_definitions.cpp.
namespace littermap::bag {
namespace {

template <typename T, typename M>
concept MessageOf = std::same_as<std::remove_const_t<T>, M>;

template <typename T>
concept Primitive = std::is_arithmetic_v<T> && !std::same_as<T, bool>;

// --- Field lists, in .msg order -------------------------------------------------------------

void Fields(MessageOf<msg::Time> auto& m, auto&& field) {
  field(m.sec, "Time.sec");
  field(m.nanosec, "Time.nanosec");
}
void Fields(MessageOf<msg::Header> auto& m, auto&& field) {
  field(m.stamp, "Header.stamp");
  field(m.frame_id, "Header.frame_id");
}
void Fields(MessageOf<msg::String> auto& m, auto&& field) { field(m.data, "String.data"); }
void Fields(MessageOf<msg::Vector3> auto& m, auto&& field) {
  field(m.x, "Vector3.x");
  field(m.y, "Vector3.y");
  field(m.z, "Vector3.z");
}
void Fields(MessageOf<msg::Point> auto& m, auto&& field) {
  field(m.x, "Point.x");
  field(m.y, "Point.y");
  field(m.z, "Point.z");
}
void Fields(MessageOf<msg::Quaternion> auto& m, auto&& field) {
  field(m.x, "Quaternion.x");
  field(m.y, "Quaternion.y");
  field(m.z, "Quaternion.z");
  field(m.w, "Quaternion.w");
}
void Fields(MessageOf<msg::Pose> auto& m, auto&& field) {
  field(m.position, "Pose.position");
  field(m.orientation, "Pose.orientation");
}
void Fields(MessageOf<msg::PoseWithCovariance> auto& m, auto&& field) {
  field(m.pose, "PoseWithCovariance.pose");
  field(m.covariance, "PoseWithCovariance.covariance");
}
void Fields(MessageOf<msg::Twist> auto& m, auto&& field) {
  field(m.linear, "Twist.linear");
  field(m.angular, "Twist.angular");
}
void Fields(MessageOf<msg::TwistWithCovariance> auto& m, auto&& field) {
  field(m.twist, "TwistWithCovariance.twist");
  field(m.covariance, "TwistWithCovariance.covariance");
}
void Fields(MessageOf<msg::Transform> auto& m, auto&& field) {
  field(m.translation, "Transform.translation");
  field(m.rotation, "Transform.rotation");
}
void Fields(MessageOf<msg::TransformStamped> auto& m, auto&& field) {
  field(m.header, "TransformStamped.header");
  field(m.child_frame_id, "TransformStamped.child_frame_id");
  field(m.transform, "TransformStamped.transform");
}
void Fields(MessageOf<msg::TFMessage> auto& m, auto&& field) {
  field(m.transforms, "TFMessage.transforms");
}
void Fields(MessageOf<msg::LaserScan> auto& m, auto&& field) {
  field(m.header, "LaserScan.header");
  field(m.angle_min, "LaserScan.angle_min");
  field(m.angle_max, "LaserScan.angle_max");
  field(m.angle_increment, "LaserScan.angle_increment");
  field(m.time_increment, "LaserScan.time_increment");
  field(m.scan_time, "LaserScan.scan_time");
  field(m.range_min, "LaserScan.range_min");
  field(m.range_max, "LaserScan.range_max");
  field(m.ranges, "LaserScan.ranges");
  field(m.intensities, "LaserScan.intensities");
}
void Fields(MessageOf<msg::Image> auto& m, auto&& field) {
  field(m.header, "Image.header");
  field(m.height, "Image.height");
  field(m.width, "Image.width");
  field(m.encoding, "Image.encoding");
  field(m.is_bigendian, "Image.is_bigendian");
  field(m.step, "Image.step");
  field(m.data, "Image.data");
}
void Fields(MessageOf<msg::CompressedImage> auto& m, auto&& field) {
  field(m.header, "CompressedImage.header");
  field(m.format, "CompressedImage.format");
  field(m.data, "CompressedImage.data");
}
void Fields(MessageOf<msg::RegionOfInterest> auto& m, auto&& field) {
  field(m.x_offset, "RegionOfInterest.x_offset");
  field(m.y_offset, "RegionOfInterest.y_offset");
  field(m.height, "RegionOfInterest.height");
  field(m.width, "RegionOfInterest.width");
  field(m.do_rectify, "RegionOfInterest.do_rectify");
}
void Fields(MessageOf<msg::CameraInfo> auto& m, auto&& field) {
  field(m.header, "CameraInfo.header");
  field(m.height, "CameraInfo.height");
  field(m.width, "CameraInfo.width");
  field(m.distortion_model, "CameraInfo.distortion_model");
  field(m.d, "CameraInfo.d");
  field(m.k, "CameraInfo.k");
  field(m.r, "CameraInfo.r");
  field(m.p, "CameraInfo.p");
  field(m.binning_x, "CameraInfo.binning_x");
  field(m.binning_y, "CameraInfo.binning_y");
  field(m.roi, "CameraInfo.roi");
}
void Fields(MessageOf<msg::Imu> auto& m, auto&& field) {
  field(m.header, "Imu.header");
  field(m.orientation, "Imu.orientation");
  field(m.orientation_covariance, "Imu.orientation_covariance");
  field(m.angular_velocity, "Imu.angular_velocity");
  field(m.angular_velocity_covariance, "Imu.angular_velocity_covariance");
  field(m.linear_acceleration, "Imu.linear_acceleration");
  field(m.linear_acceleration_covariance, "Imu.linear_acceleration_covariance");
}
void Fields(MessageOf<msg::NavSatStatus> auto& m, auto&& field) {
  field(m.status, "NavSatStatus.status");
  field(m.service, "NavSatStatus.service");
}
void Fields(MessageOf<msg::NavSatFix> auto& m, auto&& field) {
  field(m.header, "NavSatFix.header");
  field(m.status, "NavSatFix.status");
  field(m.latitude, "NavSatFix.latitude");
  field(m.longitude, "NavSatFix.longitude");
  field(m.altitude, "NavSatFix.altitude");
  field(m.position_covariance, "NavSatFix.position_covariance");
  field(m.position_covariance_type, "NavSatFix.position_covariance_type");
}
void Fields(MessageOf<msg::Odometry> auto& m, auto&& field) {
  field(m.header, "Odometry.header");
  field(m.child_frame_id, "Odometry.child_frame_id");
  field(m.pose, "Odometry.pose");
  field(m.twist, "Odometry.twist");
}

// --- Visitors ---------------------------------------------------------------------------------
// Overload resolution picks the CDR rule for each field type: a primitive, bool (one byte),
// string, T[N] (no count, XTypes 1.3 7.4.3.5.3), T[] of primitives (count + elements), T[] of
// messages (count + each element inlined), or a nested message (inlined).

// The fewest bytes a message can take: padding counts 0 and a string its length word only (a
// zero length is accepted for an empty string). Bounds sequence counts before allocating.
struct MinBytes {
  std::size_t total = 0;
  template <Primitive T>
  void operator()(const T&, const char*) {
    total += sizeof(T);
  }
  void operator()(const bool&, const char*) { total += 1; }
  void operator()(const std::string&, const char*) { total += 4; }
  template <typename T, std::size_t N>
  void operator()(const std::array<T, N>&, const char*) {
    total += N * sizeof(T);
  }
  template <typename T>
  void operator()(const std::vector<T>&, const char*) {
    total += 4;
  }
  template <typename M>
  void operator()(const M& message, const char*) {
    Fields(message, *this);
  }
};

template <typename M>
std::size_t MinEncodedBytes() {
  static const std::size_t bytes = [] {
    const M message{};
    MinBytes visitor;
    Fields(message, visitor);
    return visitor.total;
  }();
  return bytes;
}

struct FieldWriter {
  cdr::Writer& writer;
  template <Primitive T>
  void operator()(const T& value, const char*) {
    writer.Write(value);
  }
  void operator()(const bool& value, const char*) { writer.WriteBool(value); }
  void operator()(const std::string& value, const char*) { writer.WriteString(value); }
  template <Primitive T, std::size_t N>
  void operator()(const std::array<T, N>& values, const char*) {
    writer.WriteArray(std::span<const T>(values));
  }
  template <Primitive T>
  void operator()(const std::vector<T>& values, const char*) {
    writer.WriteSequence(std::span<const T>(values));
  }
  template <typename M>
  void operator()(const std::vector<M>& values, const char*) {
    writer.WriteCount(values.size());
    for (const M& value : values) EncodeInto(writer, value);
  }
  template <typename M>
  void operator()(const M& value, const char*) {
    EncodeInto(writer, value);
  }
};

struct FieldReader {
  cdr::Reader& reader;
  template <Primitive T>
  void operator()(T& value, const char* field) {
    value = reader.Read<T>(field);
  }
  void operator()(bool& value, const char* field) { value = reader.ReadBool(field); }
  void operator()(std::string& value, const char* field) { value = reader.ReadString(field); }
  template <Primitive T, std::size_t N>
  void operator()(std::array<T, N>& values, const char* field) {
    reader.ReadArray(std::span<T>(values), field);
  }
  template <Primitive T>
  void operator()(std::vector<T>& values, const char* field) {
    values = reader.ReadSequence<T>(field);
  }
  template <typename M>
  void operator()(std::vector<M>& values, const char* field) {
    values.resize(reader.ReadCount(MinEncodedBytes<M>(), field));
    for (M& value : values) DecodeFrom(reader, value);
  }
  template <typename M>
  void operator()(M& value, const char*) {
    DecodeFrom(reader, value);
  }
};

}  // namespace

#define LITTERMAP_DEFINE_CODEC(Type)                             \
  void EncodeInto(cdr::Writer& writer, const msg::Type& value) { \
    Fields(value, FieldWriter{writer});                          \
  }                                                              \
  void DecodeFrom(cdr::Reader& reader, msg::Type& value) { Fields(value, FieldReader{reader}); }

LITTERMAP_DEFINE_CODEC(Time)
LITTERMAP_DEFINE_CODEC(Header)
LITTERMAP_DEFINE_CODEC(String)
LITTERMAP_DEFINE_CODEC(Vector3)
LITTERMAP_DEFINE_CODEC(Point)
LITTERMAP_DEFINE_CODEC(Quaternion)
LITTERMAP_DEFINE_CODEC(Pose)
LITTERMAP_DEFINE_CODEC(PoseWithCovariance)
LITTERMAP_DEFINE_CODEC(Twist)
LITTERMAP_DEFINE_CODEC(TwistWithCovariance)
LITTERMAP_DEFINE_CODEC(Transform)
LITTERMAP_DEFINE_CODEC(TransformStamped)
LITTERMAP_DEFINE_CODEC(TFMessage)
LITTERMAP_DEFINE_CODEC(LaserScan)
LITTERMAP_DEFINE_CODEC(Image)
LITTERMAP_DEFINE_CODEC(CompressedImage)
LITTERMAP_DEFINE_CODEC(RegionOfInterest)
LITTERMAP_DEFINE_CODEC(CameraInfo)
LITTERMAP_DEFINE_CODEC(Imu)
LITTERMAP_DEFINE_CODEC(NavSatStatus)
LITTERMAP_DEFINE_CODEC(NavSatFix)
LITTERMAP_DEFINE_CODEC(Odometry)

#undef LITTERMAP_DEFINE_CODEC

}  // namespace littermap::bag

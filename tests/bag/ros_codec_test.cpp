// CDR codec of the ROS 2 message types. The byte-exact vectors were worked out by hand from the
// XCDR1 rules (XTypes 1.3, 7.4.3.5): fields in .msg order, each primitive aligned to its size
// counted from the first byte after the 4-byte encapsulation header, strings as a uint32 length
// that includes the NUL, sequences as a uint32 count, fixed arrays without a count. Offsets in
// the comments are relative to that first byte after the header; IEEE-754 bit patterns are
// little-endian.

#include "bag/ros_codec.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace littermap::bag {
namespace {

using Bytes = std::vector<std::uint8_t>;

// --- Byte-exact vectors -------------------------------------------------------------------

// std_msgs/String{data: "hello"}.
const Bytes kStringHello = {
    0x00, 0x01, 0x00, 0x00,             // encapsulation: CDR_LE, options 0
    0x06, 0x00, 0x00, 0x00,             // 0: length 6 = "hello" + NUL
    'h',  'e',  'l',  'l',  'o', 0x00,  // 4..9
};

// sensor_msgs/LaserScan with frame_id "laser", 3 ranges and 2 intensities.
const Bytes kLaserScan = {
    0x00, 0x01, 0x00, 0x00,             // encapsulation
    0x00, 0xF1, 0x53, 0x65,             // 0: stamp.sec 1700000000 = 0x6553F100
    0x00, 0x65, 0xCD, 0x1D,             // 4: stamp.nanosec 500000000 = 0x1DCD6500
    0x06, 0x00, 0x00, 0x00,             // 8: frame_id length 6
    'l',  'a',  's',  'e',  'r', 0x00,  // 12..17: "laser\0"
    0x00, 0x00,                         // 18: pad to 20 for float32
    0x00, 0x00, 0xC0, 0xBF,             // 20: angle_min -1.5 = 0xBFC00000
    0x00, 0x00, 0xC0, 0x3F,             // 24: angle_max 1.5 = 0x3FC00000
    0x00, 0x00, 0xC0, 0x3F,             // 28: angle_increment 1.5
    0x00, 0x00, 0x80, 0x3A,             // 32: time_increment 2^-10 = 0x3A800000
    0x00, 0x00, 0x00, 0x3E,             // 36: scan_time 0.125 = 0x3E000000
    0x00, 0x00, 0x00, 0x3F,             // 40: range_min 0.5 = 0x3F000000
    0x00, 0x00, 0x80, 0x41,             // 44: range_max 16 = 0x41800000
    0x03, 0x00, 0x00, 0x00,             // 48: ranges count 3
    0x00, 0x00, 0x80, 0x3F,             // 52: 1.0
    0x00, 0x00, 0x00, 0x40,             // 56: 2.0
    0x00, 0x00, 0x80, 0x40,             // 60: 4.0
    0x02, 0x00, 0x00, 0x00,             // 64: intensities count 2
    0x00, 0x00, 0xC8, 0x42,             // 68: 100.0 = 0x42C80000
    0x00, 0x00, 0x00, 0x3F,             // 72: 0.5
};
constexpr std::size_t kLaserScanRangesCountAt = 4 + 48;
constexpr std::size_t kLaserScanFrameIdNulAt = 4 + 17;

msg::LaserScan LaserScanOfVector() {
  msg::LaserScan scan;
  scan.header.stamp = {1700000000, 500000000};
  scan.header.frame_id = "laser";
  scan.angle_min = -1.5F;
  scan.angle_max = 1.5F;
  scan.angle_increment = 1.5F;
  scan.time_increment = 1.0F / 1024;
  scan.scan_time = 0.125F;
  scan.range_min = 0.5F;
  scan.range_max = 16.0F;
  scan.ranges = {1.0F, 2.0F, 4.0F};
  scan.intensities = {100.0F, 0.5F};
  return scan;
}

// geometry_msgs/TransformStamped: the odd-length child_frame_id leaves the stream at offset 26,
// so the first float64 needs 6 bytes of padding. Aligning to the start of the buffer (which
// includes the header) instead would give 2 — the classic CDR mistake.
const Bytes kTransformStamped = {
    0x00, 0x01, 0x00, 0x00,                          // encapsulation
    0x00, 0xF1, 0x53, 0x65,                          // 0: stamp.sec 1700000000
    0x80, 0xB2, 0xE6, 0x0E,                          // 4: stamp.nanosec 250000000 = 0x0EE6B280
    0x04, 0x00, 0x00, 0x00,                          // 8: frame_id length 4
    'm',  'a',  'p',  0x00,                          // 12..15: "map\0"
    0x06, 0x00, 0x00, 0x00,                          // 16: child_frame_id length 6
    'r',  'o',  'b',  'o',  't',  0x00,              // 20..25: "robot\0"
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00,              // 26: pad to 32 for float64
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // 32: translation.x 1.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0,  // 40: translation.y -2.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE0, 0x3F,  // 48: translation.z 0.5
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 56: rotation.x 0.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0x3F,  // 64: rotation.y 0.25
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE0, 0x3F,  // 72: rotation.z 0.5
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE8, 0x3F,  // 80: rotation.w 0.75
};

// sensor_msgs/NavSatFix: int8 then uint16 (2-byte alignment), then float64 after a 4-byte gap,
// and a trailing uint8.
const Bytes kNavSatFix = {
    0x00, 0x01, 0x00, 0x00,                          // encapsulation
    0x00, 0xF1, 0x53, 0x65,                          // 0: stamp.sec 1700000000
    0x01, 0x00, 0x00, 0x00,                          // 4: stamp.nanosec 1
    0x04, 0x00, 0x00, 0x00,                          // 8: frame_id length 4
    'g',  'p',  's',  0x00,                          // 12..15: "gps\0"
    0xFF,                                            // 16: status.status -1 (STATUS_NO_FIX)
    0x00,                                            // 17: pad to 18 for uint16
    0x09, 0x00,                                      // 18: status.service GPS|GALILEO = 9
    0x00, 0x00, 0x00, 0x00,                          // 20: pad to 24 for float64
    0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x45, 0x40,  // 24: latitude 43.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x60, 0x56, 0xC0,  // 32: longitude -89.5
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x70, 0x40,  // 40: altitude 256.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // 48: position_covariance[0] 1.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 56: [1]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 64: [2]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 72: [3]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // 80: [4] 1.0
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 88: [5]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 96: [6]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // 104: [7]
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x40,  // 112: [8] 4.0
    0x02,                                            // 120: COVARIANCE_TYPE_DIAGONAL_KNOWN
};

TEST(RosCodecBytes, StringHello) {
  EXPECT_EQ(Encode(msg::String{"hello"}), kStringHello);
  EXPECT_EQ(Decode<msg::String>(kStringHello).data, "hello");
}

TEST(RosCodecBytes, LaserScanWithIntensities) {
  EXPECT_EQ(Encode(LaserScanOfVector()), kLaserScan);
  EXPECT_EQ(Decode<msg::LaserScan>(kLaserScan), LaserScanOfVector());
}

TEST(RosCodecBytes, LaserScanWithoutIntensities) {
  // The same bytes up to offset 64, where the intensities count becomes 0 and the message ends.
  Bytes bytes(kLaserScan.begin(), kLaserScan.begin() + 4 + 68);
  bytes[4 + 64] = 0x00;
  msg::LaserScan scan = LaserScanOfVector();
  scan.intensities.clear();
  EXPECT_EQ(Encode(scan), bytes);
  EXPECT_EQ(Decode<msg::LaserScan>(bytes), scan);
}

TEST(RosCodecBytes, TransformStampedPadsToEightAfterOddString) {
  msg::TransformStamped tf;
  tf.header = {{1700000000, 250000000}, "map"};
  tf.child_frame_id = "robot";
  tf.transform.translation = {1.0, -2.0, 0.5};
  tf.transform.rotation = {0.0, 0.25, 0.5, 0.75};
  EXPECT_EQ(Encode(tf), kTransformStamped);
  EXPECT_EQ(Decode<msg::TransformStamped>(kTransformStamped), tf);
}

TEST(RosCodecBytes, NavSatFixMixedAlignment) {
  msg::NavSatFix fix;
  fix.header = {{1700000000, 1}, "gps"};
  fix.status = {-1, 9};
  fix.latitude = 43.0;
  fix.longitude = -89.5;
  fix.altitude = 256.0;
  fix.position_covariance = {1, 0, 0, 0, 1, 0, 0, 0, 4};
  fix.position_covariance_type = 2;
  EXPECT_EQ(Encode(fix), kNavSatFix);
  EXPECT_EQ(Decode<msg::NavSatFix>(kNavSatFix), fix);
}

// --- Malformed input ----------------------------------------------------------------------

std::string DecodeError(const Bytes& bytes) {
  try {
    Decode<msg::LaserScan>(bytes);
  } catch (const cdr::CdrError& error) {
    return error.what();
  }
  return "";
}

TEST(RosCodecMalformed, HugeSequenceCountThrowsBeforeAllocating) {
  Bytes bytes = kLaserScan;
  std::fill_n(bytes.begin() + kLaserScanRangesCountAt, 4, 0xFF);  // 0xFFFFFFFF ranges
  EXPECT_NE(DecodeError(bytes).find("LaserScan.ranges"), std::string::npos);
}

TEST(RosCodecMalformed, HugeCountOfEveryVariableLengthField) {
  // A message whose last field is a sequence ends in its count; make that count 0xFFFFFFFF.
  const auto huge_tail = [](Bytes bytes) {
    std::fill(bytes.end() - 4, bytes.end(), 0xFF);
    return bytes;
  };
  EXPECT_THROW(Decode<msg::Image>(huge_tail(Encode(msg::Image{}))), cdr::CdrError);
  EXPECT_THROW(Decode<msg::CompressedImage>(huge_tail(Encode(msg::CompressedImage{}))),
               cdr::CdrError);
  EXPECT_THROW(Decode<msg::TFMessage>(huge_tail(Encode(msg::TFMessage{}))), cdr::CdrError);
}

TEST(RosCodecMalformed, TransformCountBoundedByMinimumElementSize) {
  // Two transforms claimed but only bytes for one: rejected by the count check, not by running
  // off the end in the second element.
  msg::TFMessage message;
  message.transforms.resize(1);
  Bytes bytes = Encode(message);
  bytes[4] = 2;
  try {
    Decode<msg::TFMessage>(bytes);
    FAIL() << "no exception";
  } catch (const cdr::CdrError& error) {
    EXPECT_NE(std::string(error.what()).find("'TFMessage.transforms' claims 2"), std::string::npos)
        << error.what();
  }
}

TEST(RosCodecMalformed, WrongEncapsulation) {
  for (const int kind : {0x00, 0x02, 0x03, 0x07, 0x0B}) {
    Bytes bytes = kStringHello;
    bytes[1] = static_cast<std::uint8_t>(kind);
    EXPECT_THROW(Decode<msg::String>(bytes), cdr::CdrError) << kind;
  }
}

TEST(RosCodecMalformed, StringWithoutNul) {
  Bytes bytes = kStringHello;
  bytes.back() = '!';
  EXPECT_THROW(Decode<msg::String>(bytes), cdr::CdrError);

  Bytes scan = kLaserScan;
  scan[kLaserScanFrameIdNulAt] = 'x';
  EXPECT_NE(DecodeError(scan).find("Header.frame_id"), std::string::npos);
}

TEST(RosCodecMalformed, TrailingPaddingAccepted) {
  // DDS pads a serialized payload to a multiple of 4: "hello" ends at 14, padded to 16.
  Bytes bytes = kStringHello;
  bytes.insert(bytes.end(), {0x00, 0x00});
  EXPECT_EQ(Decode<msg::String>(bytes).data, "hello");
}

// --- Every type: round trip, prefixes, definitions ------------------------------------------

template <std::size_t N>
std::array<double, N> Ramp(double start, double step) {
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i) values[i] = start + step * static_cast<double>(i);
  return values;
}

// One instance of M with every field away from its default.
template <typename M>
M Sample();

template <>
msg::Time Sample() {
  return {-17, 999999999};
}
template <>
msg::Header Sample() {
  return {Sample<msg::Time>(), "camera_color_optical_frame"};
}
template <>
msg::String Sample() {
  return {"litter \xE2\x99\xBB ok"};
}  // UTF-8 passes through
template <>
msg::Vector3 Sample() {
  return {1.25, -2.5, 3.75};
}
template <>
msg::Point Sample() {
  return {10.5, -20.25, 0.125};
}
template <>
msg::Quaternion Sample() {
  return {0.1, -0.2, 0.3, 0.9};
}
template <>
msg::Pose Sample() {
  return {Sample<msg::Point>(), Sample<msg::Quaternion>()};
}
template <>
msg::PoseWithCovariance Sample() {
  return {Sample<msg::Pose>(), Ramp<36>(0.5, 0.25)};
}
template <>
msg::Twist Sample() {
  return {Sample<msg::Vector3>(), {-0.5, 0.25, 7.0}};
}
template <>
msg::TwistWithCovariance Sample() {
  return {Sample<msg::Twist>(), Ramp<36>(-3.0, 0.125)};
}
template <>
msg::Transform Sample() {
  return {Sample<msg::Vector3>(), Sample<msg::Quaternion>()};
}
template <>
msg::TransformStamped Sample() {
  return {Sample<msg::Header>(), "base_link", Sample<msg::Transform>()};
}
template <>
msg::TFMessage Sample() {
  msg::TransformStamped second = Sample<msg::TransformStamped>();
  second.child_frame_id = "laser";
  second.transform.translation.z = 0.3;
  return {{Sample<msg::TransformStamped>(), second}};
}
template <>
msg::LaserScan Sample() {
  return {Sample<msg::Header>(),
          -2.0F,
          2.0F,
          0.01F,
          1e-4F,
          0.1F,
          0.05F,
          30.0F,
          {1.0F, 1.5F, 29.0F, 0.2F},
          {10.0F, 20.0F, 30.0F, 40.0F}};
}
template <>
msg::Image Sample() {
  std::vector<std::uint8_t> data(2 * 9);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 13 + 1);
  return {Sample<msg::Header>(), 2, 3, "rgb8", 1, 9, data};
}
template <>
msg::CompressedImage Sample() {
  return {Sample<msg::Header>(), "rgb8; jpeg compressed bgr8", {0xFF, 0xD8, 0xFF, 0xE0, 0x00}};
}
template <>
msg::RegionOfInterest Sample() {
  return {10, 20, 30, 40, true};
}
template <>
msg::CameraInfo Sample() {
  return {Sample<msg::Header>(),
          480,
          640,
          "plumb_bob",
          {0.1, -0.2, 0.001, 0.002, 0.05},
          Ramp<9>(1, 1),
          Ramp<9>(-1, 0.5),
          Ramp<12>(100, 7),
          2,
          3,
          Sample<msg::RegionOfInterest>()};
}
template <>
msg::Imu Sample() {
  return {Sample<msg::Header>(),  Sample<msg::Quaternion>(), Ramp<9>(0.1, 0.1),
          Sample<msg::Vector3>(), Ramp<9>(0.2, 0.2),         {0.0, 0.1, 9.81},
          Ramp<9>(0.3, 0.3)};
}
template <>
msg::NavSatStatus Sample() {
  return {2, 15};
}
template <>
msg::NavSatFix Sample() {
  return {Sample<msg::Header>(),
          Sample<msg::NavSatStatus>(),
          43.0731,
          -89.4012,
          270.5,
          Ramp<9>(0.5, 0.5),
          3};
}
template <>
msg::Odometry Sample() {
  return {Sample<msg::Header>(), "base_link", Sample<msg::PoseWithCovariance>(),
          Sample<msg::TwistWithCovariance>()};
}

using AllMessages =
    ::testing::Types<msg::Time, msg::Header, msg::String, msg::Vector3, msg::Point, msg::Quaternion,
                     msg::Pose, msg::PoseWithCovariance, msg::Twist, msg::TwistWithCovariance,
                     msg::Transform, msg::TransformStamped, msg::TFMessage, msg::LaserScan,
                     msg::Image, msg::CompressedImage, msg::RegionOfInterest, msg::CameraInfo,
                     msg::Imu, msg::NavSatStatus, msg::NavSatFix, msg::Odometry>;

struct MessageName {
  template <typename M>
  static std::string GetName(int) {
    std::string name(MessageTraits<M>::kTypeName);
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
  }
};

template <typename M>
class RosCodecAllTypes : public ::testing::Test {};
TYPED_TEST_SUITE(RosCodecAllTypes, AllMessages, MessageName);

TYPED_TEST(RosCodecAllTypes, SampleDiffersFromDefault) {
  EXPECT_FALSE(Sample<TypeParam>() == TypeParam{});
}

TYPED_TEST(RosCodecAllTypes, RoundTrip) {
  const TypeParam original = Sample<TypeParam>();
  EXPECT_EQ(Decode<TypeParam>(Encode(original)), original);
  EXPECT_EQ(Decode<TypeParam>(Encode(TypeParam{})), TypeParam{});
}

TYPED_TEST(RosCodecAllTypes, EveryStrictPrefixThrows) {
  const Bytes bytes = Encode(Sample<TypeParam>());
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    // A copy of exactly `size` bytes, so that ASan sees any read past the end.
    const Bytes prefix(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
    EXPECT_THROW(Decode<TypeParam>(prefix), cdr::CdrError) << size << " of " << bytes.size();
  }
}

TYPED_TEST(RosCodecAllTypes, TrailingPaddingAccepted) {
  Bytes bytes = Encode(Sample<TypeParam>());
  bytes.insert(bytes.end(), 3, 0x00);
  EXPECT_EQ(Decode<TypeParam>(bytes), Sample<TypeParam>());
}

// Splits a ros2msg definition into {"": top-level text, "pkg/Type": text, ...}.
std::vector<std::pair<std::string, std::string>> Sections(std::string_view definition) {
  std::vector<std::pair<std::string, std::string>> sections = {{"", ""}};
  std::istringstream lines{std::string(definition)};
  for (std::string line; std::getline(lines, line);) {
    if (line == std::string(80, '=')) {
      std::getline(lines, line);
      EXPECT_EQ(line.rfind("MSG: ", 0), 0U) << line;
      sections.emplace_back(line.substr(5), "");
    } else {
      sections.back().second += line + "\n";
    }
  }
  return sections;
}

TYPED_TEST(RosCodecAllTypes, DefinitionIsClosedAndHasEachDependencyOnce) {
  const auto sections = Sections(MessageTraits<TypeParam>::Definition());
  std::set<std::string> defined;
  for (const auto& [name, text] : sections) {
    EXPECT_FALSE(text.empty()) << name;
    if (!name.empty()) {
      EXPECT_TRUE(defined.insert(name).second) << name << " twice";
    }
  }
  const std::set<std::string> primitives = {"bool",   "byte",  "char",   "float32", "float64",
                                            "int8",   "uint8", "int16",  "uint16",  "int32",
                                            "uint32", "int64", "uint64", "string"};
  const std::string package(
      MessageTraits<TypeParam>::kTypeName.substr(0, MessageTraits<TypeParam>::kTypeName.find('/')));
  for (const auto& [name, text] : sections) {
    const std::string context = name.empty() ? package : name.substr(0, name.find('/'));
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::string type = line.substr(0, line.find_first_of("[ "));
      if (primitives.contains(type)) continue;
      if (type.find('/') == std::string::npos) type = context + "/" + type;
      EXPECT_TRUE(defined.contains(type)) << type << " used by '" << name << "' not defined";
    }
  }
}

TEST(RosCodecDefinition, LeafTypeHasNoSections) {
  EXPECT_EQ(MessageTraits<msg::Time>::Definition(), "int32 sec\nuint32 nanosec\n");
  EXPECT_EQ(MessageTraits<msg::String>::Definition(), "string data\n");
}

TEST(RosCodecDefinition, LaserScanExact) {
  const std::string rule(80, '=');
  const std::string expected =
      "std_msgs/Header header\n"
      "float32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
      "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
      "float32[] ranges\nfloat32[] intensities\n" +
      rule + "\nMSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n" + rule +
      "\nMSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n";
  EXPECT_EQ(MessageTraits<msg::LaserScan>::Definition(), expected);
}

TEST(RosCodecDefinition, OdometryListsEveryNestedTypeInDepthFirstOrder) {
  std::vector<std::string> names;
  for (const auto& [name, text] : Sections(MessageTraits<msg::Odometry>::Definition())) {
    names.push_back(name);
  }
  // rosbag2 visits each type's dependencies in name order, depth first.
  const std::vector<std::string> expected = {"",
                                             "geometry_msgs/PoseWithCovariance",
                                             "geometry_msgs/Pose",
                                             "geometry_msgs/Point",
                                             "geometry_msgs/Quaternion",
                                             "geometry_msgs/TwistWithCovariance",
                                             "geometry_msgs/Twist",
                                             "geometry_msgs/Vector3",
                                             "std_msgs/Header",
                                             "builtin_interfaces/Time"};
  EXPECT_EQ(names, expected);
}

}  // namespace
}  // namespace littermap::bag

// The ros2msg text of each message type (common_interfaces / rcl_interfaces / geometry2,
// rolling; comments dropped, constants and default values kept) and the complete definition that
// rosbag2 stores as `encoded_message_definition` with encoding "ros2msg": the type's own text,
// then for each type it depends on, transitively and once each, a line of 80 '=', a line
// "MSG: pkg/Type" and that type's text (rosbag2 docs/message_definition_encoding.md). Like
// rosbag2's LocalMessageDefinitionSource, dependencies are found by parsing the field types out
// of the text and visited depth-first in name order, so the sections come in the order
// `ros2 bag record` writes them (without its comments and blank lines).

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_set>

#include "bag/ros_codec.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

struct MsgText {
  std::string_view name;  // "pkg/Type", as in a "MSG:" line and in field types
  std::string_view text;
};

constexpr MsgText kMsgTexts[] = {
    {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
    {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
    {"std_msgs/String", "string data\n"},
    {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
    {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
    {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
    {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
    {"geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n"},
    {"geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n"},
    {"geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n"},
    {"geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation\n"},
    {"geometry_msgs/TransformStamped",
     "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"},
    {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
    {"sensor_msgs/LaserScan",
     "std_msgs/Header header\n"
     "float32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
     "float32 time_increment\nfloat32 scan_time\n"
     "float32 range_min\nfloat32 range_max\n"
     "float32[] ranges\nfloat32[] intensities\n"},
    {"sensor_msgs/Image",
     "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\n"
     "uint8 is_bigendian\nuint32 step\nuint8[] data\n"},
    {"sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data\n"},
    {"sensor_msgs/RegionOfInterest",
     "uint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool do_rectify\n"},
    {"sensor_msgs/CameraInfo",
     "std_msgs/Header header\nuint32 height\nuint32 width\nstring distortion_model\n"
     "float64[] d\nfloat64[9] k\nfloat64[9] r\nfloat64[12] p\n"
     "uint32 binning_x\nuint32 binning_y\nRegionOfInterest roi\n"},
    {"sensor_msgs/Imu",
     "std_msgs/Header header\n"
     "geometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
     "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
     "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n"},
    {"sensor_msgs/NavSatStatus",
     "int8 STATUS_UNKNOWN = -2\nint8 STATUS_NO_FIX = -1\nint8 STATUS_FIX = 0\n"
     "int8 STATUS_SBAS_FIX = 1\nint8 STATUS_GBAS_FIX = 2\n"
     "int8 status -2\n"
     "uint16 SERVICE_UNKNOWN = 0\nuint16 SERVICE_GPS = 1\nuint16 SERVICE_GLONASS = 2\n"
     "uint16 SERVICE_COMPASS = 4\nuint16 SERVICE_GALILEO = 8\n"
     "uint16 service\n"},
    {"sensor_msgs/NavSatFix",
     "std_msgs/Header header\nNavSatStatus status\n"
     "float64 latitude\nfloat64 longitude\nfloat64 altitude\n"
     "float64[9] position_covariance\n"
     "uint8 COVARIANCE_TYPE_UNKNOWN = 0\nuint8 COVARIANCE_TYPE_APPROXIMATED = 1\n"
     "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN = 2\nuint8 COVARIANCE_TYPE_KNOWN = 3\n"
     "uint8 position_covariance_type\n"},
    {"nav_msgs/Odometry",
     "std_msgs/Header header\nstring child_frame_id\n"
     "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n"},
};

const std::string_view kDelimiter =
    "================================================================================\n";

std::string_view TextOf(std::string_view name) {
  for (const MsgText& msg : kMsgTexts) {
    if (msg.name == name) return msg.text;
  }
  // Every name reaching here comes from kMsgTexts itself; a miss is a typo in the table above.
  throw InternalError("no .msg text for message type '" + std::string(name) + "'");
}

bool IsPrimitive(std::string_view type) {
  static const std::unordered_set<std::string_view> kPrimitives = {
      "bool",  "byte",   "char",  "float32", "float64", "int8",   "uint8",
      "int16", "uint16", "int32", "uint32",  "int64",   "uint64", "string"};
  return kPrimitives.contains(type);
}

// The message types a .msg text uses, fully qualified with `package` when written without one.
// Constant lines ("int8 X = 1") start with a primitive type, so they need no special case.
std::set<std::string> Dependencies(std::string_view text, std::string_view package) {
  std::set<std::string> dependencies;
  std::istringstream lines{std::string(text)};
  for (std::string line; std::getline(lines, line);) {
    std::string type;
    std::istringstream(line) >> type;
    type = type.substr(0, type.find('['));  // "Type[]", "float64[9]"
    if (type.empty() || IsPrimitive(type)) continue;
    dependencies.insert(type.find('/') == std::string::npos ? std::string(package) + "/" + type
                                                            : type);
  }
  return dependencies;
}

void AppendWithDependencies(std::string_view name, std::unordered_set<std::string>& seen,
                            std::string& out) {
  const std::string_view text = TextOf(name);
  out += text;
  for (const std::string& dependency : Dependencies(text, name.substr(0, name.find('/')))) {
    if (!seen.insert(dependency).second) continue;
    out += kDelimiter;
    out += "MSG: " + dependency + "\n";
    AppendWithDependencies(dependency, seen, out);
  }
}

// "sensor_msgs/msg/LaserScan" -> "sensor_msgs/LaserScan".
std::string ShortName(std::string_view ros_name) {
  const std::size_t slash = ros_name.find('/');
  return std::string(ros_name.substr(0, slash)) + std::string(ros_name.substr(ros_name.rfind('/')));
}

template <typename M>
std::string_view FullDefinition() {
  static const std::string definition = [] {
    std::string out;
    std::unordered_set<std::string> seen;
    AppendWithDependencies(ShortName(MessageTraits<M>::kTypeName), seen, out);
    return out;
  }();
  return definition;
}

}  // namespace

#define LITTERMAP_DEFINE_DEFINITION(Type) \
  std::string_view MessageTraits<msg::Type>::Definition() { return FullDefinition<msg::Type>(); }

LITTERMAP_DEFINE_DEFINITION(Time)
LITTERMAP_DEFINE_DEFINITION(Header)
LITTERMAP_DEFINE_DEFINITION(String)
LITTERMAP_DEFINE_DEFINITION(Vector3)
LITTERMAP_DEFINE_DEFINITION(Point)
LITTERMAP_DEFINE_DEFINITION(Quaternion)
LITTERMAP_DEFINE_DEFINITION(Pose)
LITTERMAP_DEFINE_DEFINITION(PoseWithCovariance)
LITTERMAP_DEFINE_DEFINITION(Twist)
LITTERMAP_DEFINE_DEFINITION(TwistWithCovariance)
LITTERMAP_DEFINE_DEFINITION(Transform)
LITTERMAP_DEFINE_DEFINITION(TransformStamped)
LITTERMAP_DEFINE_DEFINITION(TFMessage)
LITTERMAP_DEFINE_DEFINITION(LaserScan)
LITTERMAP_DEFINE_DEFINITION(Image)
LITTERMAP_DEFINE_DEFINITION(CompressedImage)
LITTERMAP_DEFINE_DEFINITION(RegionOfInterest)
LITTERMAP_DEFINE_DEFINITION(CameraInfo)
LITTERMAP_DEFINE_DEFINITION(Imu)
LITTERMAP_DEFINE_DEFINITION(NavSatStatus)
LITTERMAP_DEFINE_DEFINITION(NavSatFix)
LITTERMAP_DEFINE_DEFINITION(Odometry)

#undef LITTERMAP_DEFINE_DEFINITION

}  // namespace littermap::bag

// libFuzzer target: decodes the input as every ROS 2 message type littermap reads. Malformed
// input must end in a littermap::Error (cdr::CdrError); anything else (a crash, a sanitizer
// report, another exception, an out-of-memory) is a bug. A message that does decode must
// re-encode to bytes that decode and re-encode to the same bytes (comparing bytes rather than
// messages, so NaN fields compare equal).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bag/ros_codec.hpp"
#include "core/error.hpp"

namespace {

using littermap::bag::Decode;
using littermap::bag::Encode;

template <typename M>
void DecodeAs(std::span<const std::uint8_t> bytes) {
  try {
    const std::vector<std::uint8_t> encoded = Encode(Decode<M>(bytes));
    if (Encode(Decode<M>(encoded)) != encoded) __builtin_trap();
  } catch (const littermap::Error&) {
    // Expected for malformed input.
  }
}

template <typename... M>
void DecodeAsEach(std::span<const std::uint8_t> bytes) {
  (DecodeAs<M>(bytes), ...);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace msg = littermap::msg;
  DecodeAsEach<msg::Time, msg::Header, msg::String, msg::Vector3, msg::Point, msg::Quaternion,
               msg::Pose, msg::PoseWithCovariance, msg::Twist, msg::TwistWithCovariance,
               msg::Transform, msg::TransformStamped, msg::TFMessage, msg::LaserScan, msg::Image,
               msg::CompressedImage, msg::RegionOfInterest, msg::CameraInfo, msg::Imu,
               msg::NavSatStatus, msg::NavSatFix, msg::Odometry>({data, size});
  return 0;
}

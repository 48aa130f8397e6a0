#pragma once
// One live sensor the recorder (capture/recorder.hpp) reads in its own thread: a laser, an RGB-D
// camera or the robot base's odometry. A source hands over decoded readings; encoding them for
// the bag happens off its thread.
//
// Errors: SensorDisconnectedError when the sensor is gone or cannot be
// reached (the recorder reconnects), BadInputError for one malformed reading (the source stays
// usable), UsageError for a source that can never work (a bad URI or mode).

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <opencv2/core.hpp>

#include "bag/ros_messages.hpp"
#include "capture/sensor_disconnected.hpp"
#include "core/time.hpp"

namespace littermap::capture {

// A colour image and the depth registered to it, taken together.
struct RgbdFrame {
  TimestampNs stamp_ns = 0;     // host time
  cv::Mat colour_bgr;           // CV_8UC3
  cv::Mat depth_mm;             // CV_16UC1, registered to colour; 0 = no reading
  msg::CameraInfo camera_info;  // of the colour camera; the header is the recorder's
};

using SensorSample = std::variant<msg::LaserScan, msg::Odometry, RgbdFrame>;

enum class SensorKind { kLaser, kCamera, kOdometry };

class SensorSource {
 public:
  virtual ~SensorSource() = default;

  virtual SensorKind kind() const = 0;
  virtual const std::string& uri() const = 0;
  // (Re)connects and starts streaming.
  virtual void Connect() = 0;
  // The next reading, waiting at most timeout_s; nothing on timeout.
  virtual std::optional<SensorSample> Read(double timeout_s) = 0;
  // Stops streaming and releases the sensor; never throws, safe when not connected.
  virtual void Disconnect() = 0;
  // What the source noticed since the last call that the user should know (a mode it could not
  // set, a fallback it took); the recorder writes them as events.
  virtual std::vector<std::string> TakeNotes() { return {}; }
};

// "laser", "camera", "odometry": the source's name in status lines and events.
const char* SensorName(SensorKind kind);

}  // namespace littermap::capture

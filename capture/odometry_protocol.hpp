#pragma once
// The line protocol a robot base uses to report wheel odometry to `littermap capture
// --odometry tcp://HOST:PORT` or `--odometry serial:/dev/ttyUSB0` (115200 8N1). ASCII, one
// reading per line, LF or CR LF:
//
//   $ODOM,<time_ms>,<x_m>,<y_m>,<theta_rad>,<v_mps>,<omega_radps>*HH
//
// time_ms      the base's own clock in milliseconds (unsigned, never going backwards)
// x_m y_m      position of base_link in the odom frame, as the base integrates it
// theta_rad    heading of base_link in the odom frame
// v_mps        forward speed; omega_radps turn rate (counter-clockwise positive)
// HH           two hex digits: XOR of every byte between '$' and '*', as in NMEA 0183
//
// e.g. "$ODOM,123456,1.2500,-0.3000,0.785400,0.4000,0.05000*07". Lines not starting with "$ODOM,"
// are ignored, so a base may print other things on the same link. The base sends at its own rate
// (20–100 Hz is usual); the recorder maps its clock to host time (capture/clock_offset.hpp).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/planar_pose.hpp"

namespace littermap::capture {

struct OdometryReading {
  std::uint64_t time_ms = 0;
  PlanarPose T_odom_base;
  double linear_mps = 0;
  double angular_radps = 0;
};

// The reading on `line` (without its line end); nothing for a line of another kind. Throws
// BadInputError quoting the line, prefixed by `context`, for a $ODOM line with a bad checksum,
// a missing or non-numeric field, or a non-finite value.
std::optional<OdometryReading> ParseOdometryLine(std::string_view line, const std::string& context);

// The line for `reading`, without a line end.
std::string FormatOdometryLine(const OdometryReading& reading);

}  // namespace littermap::capture

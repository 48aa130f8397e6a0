#pragma once
// CARMEN text logs (the format of the Radish data set repository): one record a line, the first
// token naming the type. The formats, as CARMEN's logger writes them in its file header:
//
//   ODOM x y theta tv rv accel timestamp hostname logger_timestamp
//   FLASER num_readings [range_readings] x y theta odom_x odom_y odom_theta
//          timestamp hostname logger_timestamp
//   ROBOTLASER1 laser_type start_angle field_of_view angular_resolution maximum_range accuracy
//          remission_mode num_readings [range_readings] num_remissions [remission_values]
//          laser_pose_x laser_pose_y laser_pose_theta robot_pose_x robot_pose_y robot_pose_theta
//          laser_tv laser_rv forward_safety_dist side_safety_dist turn_axis
//          timestamp hostname logger_timestamp
//   PARAM name value [hostname timestamp]
//   # comment
//
// In FLASER, x y theta is the laser's pose and odom_x odom_y odom_theta the robot's (CARMEN
// calls the latter "odometry", but in the corrected Radish logs both are SLAM-corrected). Angles
// are radians, distances metres, time stamps seconds. The trailing hostname and logger time
// stamp are optional here; other record types (NEFF, RLASER, RAWLASER1, ...) are returned as
// CarmenOtherRecord so the caller can count and skip them.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/planar_pose.hpp"
#include "core/progress.hpp"

namespace littermap::importers {

struct CarmenLaserRecord {
  enum class Kind { kFlaser, kRobotLaser1 };
  Kind kind = Kind::kFlaser;
  std::vector<float> ranges_m;
  // ROBOTLASER1 only (has_geometry): beam i points at start_angle_rad + i * resolution_rad.
  bool has_geometry = false;
  double start_angle_rad = 0;
  double angular_resolution_rad = 0;
  double max_range_m = 0;
  PlanarPose laser_pose;  // T_world_laser
  PlanarPose robot_pose;  // T_world_base
  double timestamp_s = 0;
};

struct CarmenOdomRecord {
  PlanarPose pose;  // T_odom_base
  double tv_mps = 0;
  double rv_radps = 0;
  double accel_mps2 = 0;
  double timestamp_s = 0;
};

struct CarmenParamRecord {
  std::string name;
  std::string value;
};

struct CarmenCommentRecord {};  // "#" lines and blank lines

struct CarmenOtherRecord {
  std::string type;  // the first token, e.g. "NEFF"
};

using CarmenRecord = std::variant<CarmenCommentRecord, CarmenParamRecord, CarmenOdomRecord,
                                  CarmenLaserRecord, CarmenOtherRecord>;

// Parses one line (without its newline). Throws BadInputError whose message names the record
// type and the field at fault, e.g. "FLASER field 'odom_x': 'abc' is not a number"; the caller
// adds the file and line. Never reads past the line, whatever it holds (fuzzed).
CarmenRecord ParseCarmenLine(std::string_view line);

// A whole log, scans and odometry in file order.
struct CarmenLog {
  std::vector<CarmenLaserRecord> scans;
  std::vector<std::uint64_t> scan_line_numbers;  // 1-based line of each scan, for messages
  std::vector<CarmenOdomRecord> odometry;
  std::map<std::string, std::string> params;           // last value wins
  std::map<std::string, std::uint64_t> skipped_types;  // unknown record types -> count
  std::uint64_t line_count = 0;
  std::uint64_t comment_line_count = 0;
};

// Reads a plain or gzip CARMEN log. Throws BadInputError "FILE:LINE: ..." for a malformed line
// and "FILE: ... after line N" for damaged gzip data.
CarmenLog ReadCarmenLog(const std::filesystem::path& path, const ProgressCallback& progress = {});

}  // namespace littermap::importers

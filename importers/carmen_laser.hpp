#pragma once
// How a CARMEN laser record becomes a sensor_msgs/LaserScan, and where the laser sits on the
// robot.
//
// Beam angles of FLASER records (which do not carry them): 180° field of view starting at -90°
// (the robot's right), counter-clockwise; with an odd beam count (181, 361) the first and last
// beams lie at ±90° (spacing 180°/(n-1)), with an even count (180, 360) the spacing is 180°/n
// and the last beam lies one step short of +90°. This is CARMEN's own carmen_laser_get_fov()
// rule, and it is the convention that draws the sharpest maps from the reference poses of every
// Radish log in shared/datasets/carmen (tests/importers/carmen_beam_angle_test.cpp checks it).
// ROBOTLASER1 records carry their angles and maximum range.
//
// "No return": the sensor reports its maximum (81.91 m, 81.83 m, 51.15 m, 50 m, 32.767 m in the
// Radish logs, depending on the scanner mode). The scan's range_max is set just below the
// smallest such value, so those readings are > range_max and invalid by ROS convention.

#include <cstdint>
#include <span>
#include <string>

#include "bag/ros_messages.hpp"
#include "core/planar_pose.hpp"
#include "importers/carmen_log.hpp"

namespace littermap::importers {

struct CarmenBeamGeometry {
  double angle_min_rad = 0;
  double angle_increment_rad = 0;
};

// The beam angles of a record (explicit for ROBOTLASER1, the rule above for FLASER).
CarmenBeamGeometry CarmenBeams(const CarmenLaserRecord& record);

struct CarmenRangeOptions {
  double range_min_m = 0.01;  // shorter readings are invalid (0 is the usual error reading)
  // Readings at or beyond this range mean "no return". 0: ROBOTLASER1's maximum_range, or for
  // FLASER logs the readings within max(no_return_band_min_m, no_return_band_fraction * max) of
  // the log's largest reading (the scanner's "no return" value and its few neighbours).
  double no_return_range_m = 0;
  double no_return_band_fraction = 0.01;
  double no_return_band_min_m = 0.5;
};

struct CarmenRangeLimits {
  float range_min_m = 0;
  float range_max_m = 0;  // every "no return" reading is > range_max_m
  double no_return_range_m = 0;
  std::uint64_t no_return_readings = 0;
};

// Decides the valid range interval for all scans of a log. Throws UsageError for bad options.
CarmenRangeLimits CarmenRanges(std::span<const CarmenLaserRecord> scans,
                               const CarmenRangeOptions& options = {});

// The LaserScan of one record, with the given header (stamp and frame) and range limits.
msg::LaserScan ToLaserScan(const CarmenLaserRecord& record, const msg::Header& header,
                           const CarmenRangeLimits& limits);

struct LaserMountingOptions {
  double tolerance_m = 0.001;  // largest spread of the per-scan offsets still called constant
  double tolerance_rad = 0.001;
};

struct LaserMounting {
  PlanarPose T_base_laser;
  enum class Source { kPoses, kParam } source = Source::kPoses;
  bool constant = true;  // every per-scan offset is within the tolerance of T_base_laser
  double spread_m = 0;   // largest distance of a per-scan offset from the chosen one
  double spread_rad = 0;
  bool param_present = false;
  PlanarPose param_offset;  // robot_frontlaser_{offset,side_offset,angular_offset}
  std::string note;         // non-empty when the caller should warn (disagreement, spread)
};

// T_base_laser: from the PARAMs robot_frontlaser_offset / _side_offset / _angular_offset when the
// log has any of them (CARMEN's robot configuration), else the median over the scans of
// inverse(robot_pose) * laser_pose. Either way the per-scan offsets are checked against it; a
// disagreement or spread beyond the tolerance is described in `note`.
LaserMounting EstimateLaserMounting(const CarmenLog& log, const LaserMountingOptions& options = {});

}  // namespace littermap::importers

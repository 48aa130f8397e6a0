#pragma once
// Converts a CARMEN log (plain or gzip) into a littermap run bag:
//   /scan        sensor_msgs/msg/LaserScan, frame "laser", one per FLASER/ROBOTLASER1 record
//   /odom        nav_msgs/msg/Odometry, odom -> base_link, one per scan at the scan's stamp
//   /tf_static   tf2_msgs/msg/TFMessage (latched), base_link -> laser
// Odometry is the robot pose of each scan record (odom_x odom_y odom_theta) — in the corrected
// Radish logs that is the SLAM-corrected pose — or, with odometry_noise_seed, synthetic noisy
// odometry made from it (importers/odometry_noise.hpp). The log's ODOM records are read and counted
// but not written: in the corrected logs they restart from the corrected pose at every scan (and
// repeat it with time stamp 0), so they are not an odometry stream. Time stamps are made strictly
// increasing (importers/monotonic_stamps.hpp); the result says how many changed.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_writer.hpp"
#include "core/progress.hpp"
#include "importers/carmen_laser.hpp"
#include "importers/monotonic_stamps.hpp"
#include "importers/odometry_noise.hpp"

namespace littermap::importers {

struct CarmenImportOptions {
  CarmenRangeOptions ranges;
  MonotonicStampOptions stamps;
  LaserMountingOptions mounting;
  std::optional<std::uint64_t> odometry_noise_seed;  // set: replace odometry with noisy odometry
  OdometryNoiseOptions odometry_noise;
  std::filesystem::path reference_path;  // non-empty: write the robot poses there (TUM format)
  bag::BagWriterOptions bag;
};

struct CarmenImportResult {
  std::uint64_t line_count = 0;
  std::uint64_t scan_count = 0;
  std::uint64_t odometry_count = 0;        // /odom messages written
  std::uint64_t odom_records_ignored = 0;  // ODOM lines in the log (see above)
  std::uint64_t param_count = 0;
  std::map<std::string, std::uint64_t> skipped_types;  // unknown record types -> count
  std::size_t beam_count_min = 0;
  std::size_t beam_count_max = 0;
  std::uint64_t stamps_changed = 0;
  bool stamps_synthesised = false;
  double duration_s = 0;  // last scan stamp minus first
  CarmenRangeLimits ranges;
  LaserMounting mounting;
  bool noisy_odometry = false;
  std::uint64_t reference_poses = 0;  // poses written to reference_path
  std::vector<std::string> warnings;  // for the user: what was repaired or looks doubtful
};

// Reads the whole log first, so a malformed line (BadInputError "FILE:LINE: ...") or damaged
// gzip data fails before the bag is created. A bag directory this call created is removed again
// if writing fails.
CarmenImportResult ImportCarmenLog(const std::filesystem::path& log_path,
                                   const std::filesystem::path& bag_path,
                                   const CarmenImportOptions& options = {},
                                   const ProgressCallback& progress = {});

// The reference (robot) poses and the stamps the importer gives them, without writing a bag:
// what --reference writes. Exposed for tests and evaluation tools.
struct CarmenTimedPoses {
  std::vector<TimestampNs> stamps_ns;
  std::vector<PlanarPose> robot_poses;  // T_world_base of each scan
  MonotonicStampResult stamp_repair;
};
CarmenTimedPoses CarmenReferencePoses(const CarmenLog& log,
                                      const MonotonicStampOptions& options = {});

}  // namespace littermap::importers

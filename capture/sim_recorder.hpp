#pragma once
// Records a simulated survey run (sim/) into a run bag exactly like a real capture: /scan
// LaserScan, /odom Odometry (drifting wheel odometry, starting at the odom origin), /imu Imu
// (noisy roll/pitch, for tilt detection), /tf_static TFMessage (base_link -> laser and
// base_link -> camera_color_optical_frame, latched), and writes the ground truth beside it
// (sim/ground_truth.hpp). The RGB-D images follow in a later version.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "capture/bag_writer.hpp"
#include "core/progress.hpp"
#include "sim/world_spec.hpp"

namespace littermap {

struct SimRecordOptions {
  std::optional<std::uint64_t> seed;  // overrides the world's seed
  double max_duration_s = std::numeric_limits<double>::infinity();
  BagWriterOptions bag;
};

struct SimRecordResult {
  std::uint64_t scans = 0;
  std::uint64_t odometry = 0;
  std::uint64_t imu = 0;
  double duration_s = 0;
  double distance_m = 0;
  bool route_completed = false;  // false when max_duration_s cut it short
  std::uint64_t litter = 0;
  std::uint64_t natural = 0;
  std::uint64_t objects = 0;  // every primitive in the world
  std::uint64_t seed = 0;
  std::string laser;      // preset name
  double simulate_s = 0;  // wall time spent ray casting and writing scans
};

// Throws BadInputError for a bad world spec, UsageError when the bag directory is not empty,
// InternalError on write failures; on error nothing it created is left behind.
SimRecordResult RecordSimulation(const sim::WorldSpec& spec, const std::filesystem::path& bag_path,
                                 const std::filesystem::path& truth_dir,
                                 const SimRecordOptions& options = {},
                                 const ProgressCallback& progress = {});

}  // namespace littermap

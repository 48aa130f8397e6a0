#pragma once
// Records a simulated survey run (sim/) into a run bag exactly like a real capture: /scan
// LaserScan, /odom Odometry (drifting wheel odometry, starting at the odom origin), /imu Imu
// (noisy roll/pitch, for tilt detection), the RGB-D camera as the TUM importer writes it
// (/camera/color/image_raw/compressed JPEG, /camera/depth/image_raw/compressed 16-bit PNG in mm,
// /camera/color/camera_info and /camera/depth/camera_info, frame camera_color_optical_frame,
// depth registered to colour), and /tf_static TFMessage (base_link -> laser and base_link ->
// camera_color_optical_frame, latched). The ground truth goes beside it (sim/ground_truth.hpp,
// sim/instance_masks.hpp). Same spec and seed: same decoded bag content.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "bag/bag_writer.hpp"
#include "core/progress.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim {

struct SimRecordOptions {
  std::optional<std::uint64_t> seed;      // overrides the world's seed (world and noise)
  std::optional<std::uint64_t> run_seed;  // sensor noise, drift and timing only: same world
  std::string route;                      // a named route of the world; empty: `route`
  std::optional<double> start_time_s;     // stamp of the first message; none: the world's
  int litter_day = 0;                     // the litter of this day (WorldSpec::litter_day)
  double max_duration_s = std::numeric_limits<double>::infinity();
  bag::BagWriterOptions bag;
  int png_compression = 1;   // zlib level of the depth PNGs (bag/image_codec.hpp)
  bool force_truth = false;  // write the truth into a folder that holds other files too
};

struct SimRecordResult {
  std::uint64_t scans = 0;
  std::uint64_t odometry = 0;
  std::uint64_t imu = 0;
  std::uint64_t frames = 0;  // RGB-D frames (colour + depth + two CameraInfo each)
  std::uint64_t masks = 0;   // instance masks written to TRUTH_DIR/masks
  double duration_s = 0;
  double distance_m = 0;
  bool route_completed = false;  // false when max_duration_s cut it short
  std::uint64_t litter = 0;
  std::uint64_t natural = 0;
  std::uint64_t objects = 0;  // every primitive in the world
  std::uint64_t seed = 0;
  std::uint64_t run_seed = 0;
  std::string route;      // the route driven
  std::string laser;      // preset name
  double simulate_s = 0;  // wall time spent simulating, encoding and writing the messages
  double render_s = 0;    // of which rendering the RGB-D frames
};

// The world spec of the run `options` ask for: seed, run seed and route applied. Throws
// BadInputError for an unknown route.
WorldSpec RunSpec(const WorldSpec& spec, const SimRecordOptions& options);

// Writes the bag, and the ground truth into truth_dir unless it is empty. Throws BadInputError
// for a bad world spec, UsageError when the bag directory is not empty, InternalError on write
// failures; on error nothing it created is left behind. Reports progress in camera frames.
SimRecordResult RecordSimulation(const WorldSpec& spec, const std::filesystem::path& bag_path,
                                 const std::filesystem::path& truth_dir,
                                 const SimRecordOptions& options = {},
                                 const ProgressCallback& progress = {});

}  // namespace littermap::sim

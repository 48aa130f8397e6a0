#pragma once
// The reconstruct stage of a run: a run bag in, a run directory out (run/run_files.hpp). With
// laser scans the SLAM pipeline runs (with the RGB-D routine when the bag has a camera); a bag
// without laser scans (an imported TUM RGB-D sequence) gets visual odometry of the camera alone.
// `littermap reconstruct` and `littermap survey` both call it.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "reconstruct/reconstruction.hpp"

namespace littermap::run {

struct ReconstructRunOptions {
  reconstruct::ReconstructionOptions reconstruction;
  // A YAML file of tuning options applied over `reconstruction` (reconstruct/options_file.hpp);
  // empty: none.
  std::filesystem::path options_file;
  // Sensor role -> topic (--topic ROLE=NAME); the other roles are found in the bag by
  // bag/sensor_roles.hpp, starting from reconstruction.topics.
  std::map<std::string, std::string> topic_roles;
  // Write into a run directory that holds other files too (core/output_folder.hpp).
  bool force_output = false;
};

struct ReconstructRunResult {
  std::filesystem::path run_dir;
  bool visual_odometry = false;  // the bag had no laser scans
  std::vector<std::string> warnings;
  double run_time_s = 0;
  double scans_per_s = 0;  // frames per second for visual odometry
  // SLAM:
  std::size_t poses = 0;
  std::size_t key_frames = 0;
  std::size_t loops_accepted = 0;
  std::size_t loops_rejected = 0;
  // Visual odometry:
  reconstruct::VisualOdometryStats visual;
};

// Validates the options, finds the sensor topics, reconstructs and writes the run directory
// (created if needed), with the topics used in sensor_roles.json.
// Throws BadInputError for a bag or options file at fault, UsageError for a run directory that
// cannot be written.
ReconstructRunResult ReconstructRun(const std::filesystem::path& bag,
                                    const std::filesystem::path& run_dir,
                                    const ReconstructRunOptions& options,
                                    const ProgressCallback& progress = {});

// What the run came to, in one line: "wrote RUN_DIR: N poses, ..." (frames for visual odometry).
std::string ReconstructSummary(const ReconstructRunResult& result);

}  // namespace littermap::run

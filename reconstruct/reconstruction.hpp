#pragma once
// `littermap reconstruct` as a library call: reads the scans, odometry and the base_link -> laser
// extrinsic of a run bag and runs the SLAM pipeline over them.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bag/header_stamps.hpp"
#include "bag/topics.hpp"
#include "core/progress.hpp"
#include "reconstruct/gyro_odometry.hpp"
#include "reconstruct/rgbd_tracker.hpp"
#include "reconstruct/slam_pipeline.hpp"
#include "reconstruct/visual_odometry.hpp"

namespace littermap::reconstruct {

struct ReconstructionOptions {
  // The IMU gives tilt for the ground-hit filter and yaw rate for the odometry's heading; the
  // RGB-D camera serves routine 3 when the bag has its topics and `rgbd` is set.
  bag::RunTopics topics;
  bag::StampSource stamps = bag::StampSource::kHeader;  // bag/header_stamps.hpp
  bool gyro_heading = true;  // turn the odometry by the IMU's yaw rate (GyroOdometry)
  GyroOdometryOptions gyro;
  bool rgbd = true;
  RgbdTrackerOptions rgbd_tracker;
  VisualOdometryOptions visual_odometry;  // for a bag with a camera and no laser
  // Odometry older than this at a scan's time counts as missing.
  double max_odometry_age_s = 0.2;
  SlamOptions slam;
  void Validate() const;
};

struct ReconstructionResult {
  std::vector<std::string> warnings;
  double run_time_s = 0;
  double scans_per_s = 0;
};

// Runs over the bag; the pipeline holds trajectory, key frames, map and quality afterwards.
// With an RGB-D tracker (the one the pipeline was made with) the camera frames are fed to it.
// Throws BadInputError if the bag has no scan topic or a message does not decode.
ReconstructionResult ReconstructBag(const std::filesystem::path& bag,
                                    const ReconstructionOptions& options, SlamPipeline* pipeline,
                                    const ProgressCallback& progress, RgbdTracker* rgbd = nullptr);

// Every scan on the topic, in bag order. Throws BadInputError naming the bag and topic when the
// topic is missing or a message does not decode.
std::vector<LaserScan> ReadScans(const std::filesystem::path& bag, const std::string& scan_topic);

// True if the bag has the scan topic; else only visual odometry can run on it.
bool HasLaser(const std::filesystem::path& bag, const ReconstructionOptions& options);

// One camera frame of a visual-odometry run.
struct VisualFrame {
  TimestampNs stamp_ns = 0;
  VisualOdometryStep step;
};

// Visual odometry over the camera frames of a bag without laser scans (thesis 2.4 alone). The
// bag needs the colour, depth and camera-info topics; a base -> camera extrinsic is not needed
// (poses are of the camera). Throws BadInputError naming the bag and topic when one is missing or
// a message does not decode.
ReconstructionResult ReconstructBagVisually(const std::filesystem::path& bag,
                                            const ReconstructionOptions& options,
                                            std::vector<VisualFrame>* frames,
                                            VisualOdometryStats* stats,
                                            const ProgressCallback& progress);

// Routine 3's tracker for the bag's camera, or null (with a warning) when options.rgbd is off
// or the bag has no colour, depth and camera-info topics. Throws BadInputError if the camera
// info or the camera's extrinsic is unusable.
std::unique_ptr<RgbdTracker> MakeRgbdTracker(const std::filesystem::path& bag,
                                             const ReconstructionOptions& options,
                                             std::vector<std::string>* warnings);

// The laser extrinsic from the bag's /tf_static (identity with a warning if absent); its
// height above base_link into *height_m when given (0 if absent).
PlanarPose ReadLaserExtrinsic(const std::filesystem::path& bag,
                              const ReconstructionOptions& options,
                              std::vector<std::string>* warnings, double* height_m = nullptr);

}  // namespace littermap::reconstruct

#include "run/reconstruct_run.hpp"

#include <cstdio>
#include <memory>

#include "core/output_folder.hpp"
#include "reconstruct/options_file.hpp"
#include "reconstruct/rgbd_tracker.hpp"
#include "reconstruct/slam_pipeline.hpp"
#include "run/run_files.hpp"
#include "run/run_writer.hpp"
#include "run/sensor_roles_file.hpp"

namespace littermap::run {
namespace {

ReconstructRunResult ReconstructVisually(const std::filesystem::path& bag,
                                         const std::filesystem::path& run_dir,
                                         const reconstruct::ReconstructionOptions& options,
                                         const ProgressCallback& progress) {
  std::vector<reconstruct::VisualFrame> frames;
  ReconstructRunResult run;
  run.run_dir = run_dir;
  run.visual_odometry = true;
  reconstruct::ReconstructionResult result =
      reconstruct::ReconstructBagVisually(bag, options, &frames, &run.visual, progress);
  result.warnings.insert(result.warnings.begin(),
                         "no laser scans on " + options.topics.scan +
                             ": visual odometry from the camera alone (no occupancy map)");
  if (run.visual.segments > 1) {
    result.warnings.push_back("tracking was lost " + std::to_string(run.visual.segments - 1) +
                              " times; each new segment starts at the last pose known");
  }
  WriteVisualRun(run_dir, frames, run.visual, result);
  run.warnings = result.warnings;
  run.run_time_s = result.run_time_s;
  run.scans_per_s = result.scans_per_s;
  return run;
}

// What the quality counts say the user should know.
void AddQualityWarnings(const reconstruct::SlamQuality& quality,
                        std::vector<std::string>* warnings) {
  if (quality.scans_without_echoes > 0) {
    warnings->push_back(std::to_string(quality.scans_without_echoes) +
                        " scans had too few valid ranges and were placed by odometry");
  }
  if (quality.stamps_backwards + quality.stamps_duplicate > 0) {
    warnings->push_back(std::to_string(quality.stamps_backwards) + " scans went back in time and " +
                        std::to_string(quality.stamps_duplicate) +
                        " repeated a time stamp; they were dropped");
  }
  if (quality.odometry_missing + quality.odometry_rejected > 0) {
    warnings->push_back("odometry missing for " + std::to_string(quality.odometry_missing) +
                        " scans and " + "implausible for " +
                        std::to_string(quality.odometry_rejected) +
                        "; a constant-velocity model stood in");
  }
}

}  // namespace

ReconstructRunResult ReconstructRun(const std::filesystem::path& bag,
                                    const std::filesystem::path& run_dir,
                                    const ReconstructRunOptions& run_options,
                                    const ProgressCallback& progress) {
  PrepareOutputFolder(run_dir, {"-o", RunFiles::Names(), run_options.force_output});
  reconstruct::ReconstructionOptions options = run_options.reconstruction;
  if (!run_options.options_file.empty()) {
    reconstruct::ApplyOptionsFile(run_options.options_file, &options);
  }
  const bag::SensorRoles roles = ResolveBagRoles(bag, run_options.topic_roles, options.topics);
  options.topics = roles.topics;
  options.Validate();
  if (!reconstruct::HasLaser(bag, options)) {
    ReconstructRunResult run = ReconstructVisually(bag, run_dir, options, progress);
    WriteSensorRoles(RunFiles(run_dir).sensor_roles(), roles);
    return run;
  }
  std::vector<std::string> warnings;
  double laser_height_m = 0;
  const PlanarPose T_base_laser =
      reconstruct::ReadLaserExtrinsic(bag, options, &warnings, &laser_height_m);
  // The ground-hit filter needs the height of the laser above the ground: base_link is on it.
  if (options.slam.points.laser_height_m == 0) options.slam.points.laser_height_m = laser_height_m;
  const std::unique_ptr<reconstruct::RgbdTracker> rgbd =
      reconstruct::MakeRgbdTracker(bag, options, &warnings);
  reconstruct::SlamPipeline pipeline(options.slam, T_base_laser, rgbd.get());
  reconstruct::ReconstructionResult result =
      reconstruct::ReconstructBag(bag, options, &pipeline, progress, rgbd.get());
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
  const reconstruct::SlamQuality& quality = pipeline.quality();
  AddQualityWarnings(quality, &result.warnings);
  WriteRun(run_dir, pipeline, result, rgbd.get());
  WriteSensorRoles(RunFiles(run_dir).sensor_roles(), roles);
  ReconstructRunResult run;
  run.run_dir = run_dir;
  run.warnings = result.warnings;
  run.run_time_s = result.run_time_s;
  run.scans_per_s = result.scans_per_s;
  run.poses = pipeline.scans().size();
  run.key_frames = quality.key_frames;
  run.loops_accepted = quality.loops_accepted;
  run.loops_rejected = quality.loops_rejected();
  return run;
}

std::string ReconstructSummary(const ReconstructRunResult& result) {
  char figures[256];
  if (result.visual_odometry) {
    std::snprintf(figures, sizeof figures,
                  "%zu of %zu frames tracked, %zu key frames, %zu segments, %.2f s (%.0f frames/s)",
                  result.visual.tracked, result.visual.frames, result.visual.key_frames,
                  result.visual.segments, result.run_time_s, result.scans_per_s);
  } else {
    std::snprintf(figures, sizeof figures,
                  "%zu poses, %zu key frames, loops %zu accepted / %zu rejected, %.2f s "
                  "(%.0f scans/s)",
                  result.poses, result.key_frames, result.loops_accepted, result.loops_rejected,
                  result.run_time_s, result.scans_per_s);
  }
  return "wrote " + result.run_dir.string() + ": " + figures;
}

}  // namespace littermap::run

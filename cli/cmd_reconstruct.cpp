// littermap reconstruct BAG -o RUN_DIR [--scan-topic T] [--odom-topic T]
// Trajectory, occupancy map and quality of a run (DESIGN.md, "The command line").

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "reconstruct/options_file.hpp"
#include "reconstruct/reconstruction.hpp"
#include "reconstruct/run_writer.hpp"
#include "reconstruct/slam_pipeline.hpp"

namespace littermap::cli {
namespace {

struct ReconstructArguments {
  std::string bag;
  std::string run_dir;
  std::string options_file;
  reconstruct::ReconstructionOptions options;
};

// A bag without laser scans (an imported TUM RGB-D sequence): visual odometry alone.
void RunVisualOdometry(const ReconstructArguments& arguments,
                       const reconstruct::ReconstructionOptions& options, CliContext& context) {
  std::vector<reconstruct::VisualFrame> frames;
  reconstruct::VisualOdometryStats stats;
  reconstruct::ReconstructionResult result = reconstruct::ReconstructBagVisually(
      arguments.bag, options, &frames, &stats, context.Progress());
  context.FinishProgress();
  result.warnings.insert(result.warnings.begin(),
                         "no laser scans on " + options.topics.scan +
                             ": visual odometry from the camera alone (no occupancy map)");
  if (stats.segments > 1) {
    result.warnings.push_back("tracking was lost " + std::to_string(stats.segments - 1) +
                              " times; each new segment starts at the last pose known");
  }
  for (const std::string& warning : result.warnings) context.Warn(warning);
  reconstruct::WriteVisualRun(arguments.run_dir, frames, stats, result);
  std::printf(
      "wrote %s: %zu of %zu frames tracked, %zu key frames, %zu segments, %.2f s "
      "(%.0f frames/s)\n",
      arguments.run_dir.c_str(), stats.tracked, stats.frames, stats.key_frames, stats.segments,
      result.run_time_s, result.scans_per_s);
}

void RunReconstruct(const ReconstructArguments& arguments, CliContext& context) {
  reconstruct::ReconstructionOptions options = arguments.options;
  if (!arguments.options_file.empty()) {
    reconstruct::ApplyOptionsFile(arguments.options_file, &options);
  }
  options.Validate();
  if (!reconstruct::HasLaser(arguments.bag, options)) {
    RunVisualOdometry(arguments, options, context);
    return;
  }
  std::vector<std::string> warnings;
  double laser_height_m = 0;
  const PlanarPose T_base_laser =
      reconstruct::ReadLaserExtrinsic(arguments.bag, options, &warnings, &laser_height_m);
  // The ground-hit filter needs the height of the laser above the ground: base_link is on it.
  if (options.slam.points.laser_height_m == 0) options.slam.points.laser_height_m = laser_height_m;
  const std::unique_ptr<reconstruct::RgbdTracker> rgbd =
      reconstruct::MakeRgbdTracker(arguments.bag, options, &warnings);
  reconstruct::SlamPipeline pipeline(options.slam, T_base_laser, rgbd.get());
  reconstruct::ReconstructionResult result = reconstruct::ReconstructBag(
      arguments.bag, options, &pipeline, context.Progress(), rgbd.get());
  context.FinishProgress();
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
  const auto& quality = pipeline.quality();
  if (quality.scans_without_echoes > 0) {
    result.warnings.push_back(std::to_string(quality.scans_without_echoes) +
                              " scans had too few valid ranges and were placed by odometry");
  }
  if (quality.stamps_backwards + quality.stamps_duplicate > 0) {
    result.warnings.push_back(
        std::to_string(quality.stamps_backwards) + " scans went back in time and " +
        std::to_string(quality.stamps_duplicate) + " repeated a time stamp; they were dropped");
  }
  if (quality.odometry_missing + quality.odometry_rejected > 0) {
    result.warnings.push_back("odometry missing for " + std::to_string(quality.odometry_missing) +
                              " scans and " + "implausible for " +
                              std::to_string(quality.odometry_rejected) +
                              "; a constant-velocity model stood in");
  }
  for (const std::string& warning : result.warnings) context.Warn(warning);
  reconstruct::WriteRun(arguments.run_dir, pipeline, result, rgbd.get());
  std::printf(
      "wrote %s: %zu poses, %zu key frames, loops %zu accepted / %zu rejected, %.2f s "
      "(%.0f scans/s)\n",
      arguments.run_dir.c_str(), pipeline.scans().size(), quality.key_frames,
      quality.loops_accepted,
      quality.loops_rejected_match + quality.loops_rejected_disagreement +
          quality.loops_rejected_after_optimisation,
      result.run_time_s, result.scans_per_s);
}

}  // namespace

void RegisterReconstructCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<ReconstructArguments>();
  CLI::App* command = context.AddCommand(
      app, "reconstruct",
      "Reconstruct trajectory and occupancy map from a bag: RUN_DIR/trajectory.tum, "
      "keyframes.tum, map.pgm, map.yaml, map.png, routines.csv, quality.json; with a camera "
      "also camera.tum and camera_sources.csv. A bag without laser scans (an imported TUM "
      "RGB-D sequence) gets visual odometry: trajectory.tum of the camera, keyframes.tum, "
      "routines.csv, quality.json");
  command->add_option("BAG", arguments->bag, "Run bag directory")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("-o,--output", arguments->run_dir, "Run directory to write")->required();
  command->add_option("--scan-topic", arguments->options.topics.scan, "LaserScan topic")
      ->capture_default_str();
  command->add_option("--odom-topic", arguments->options.topics.odometry, "Odometry topic")
      ->capture_default_str();
  command
      ->add_option("--options", arguments->options_file,
                   "YAML file of tuning options (unknown keys are errors)")
      ->check(CLI::ExistingFile);
  command->add_flag("--no-loop-closure{false}", arguments->options.slam.loop_closure,
                    "Track and map without loop closure (for comparisons)");
  command->add_flag("--no-rgbd{false}", arguments->options.rgbd,
                    "Track with the laser alone, without the RGB-D routine (for comparisons)");
  command->add_flag("--no-gyro{false}", arguments->options.gyro_heading,
                    "Turn the odometry by the wheels alone, not by the IMU's yaw rate (for "
                    "comparisons)");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunReconstruct(*arguments, context); };
  });
}

}  // namespace littermap::cli

// littermap reconstruct BAG -o RUN_DIR [--scan-topic T] [--odom-topic T]
// Trajectory, occupancy map and quality of a run (DESIGN.md, "The command line").

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/run_stages.hpp"
#include "reconstruct/options_file.hpp"
#include "reconstruct/reconstruction.hpp"
#include "run/reconstruct_run.hpp"

namespace littermap::cli {
namespace {

struct ReconstructArguments {
  std::string bag;
  std::string run_dir;
  std::string options_file;
  reconstruct::ReconstructionOptions options;
};

void RunReconstruct(const ReconstructArguments& arguments, CliContext& context) {
  reconstruct::ReconstructionOptions options = arguments.options;
  if (!arguments.options_file.empty()) {
    reconstruct::ApplyOptionsFile(arguments.options_file, &options);
  }
  ReconstructStage(arguments.bag, arguments.run_dir, options, context);
}

}  // namespace

void ReconstructStage(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                      const reconstruct::ReconstructionOptions& options, CliContext& context) {
  const run::ReconstructRunResult result =
      run::ReconstructRun(bag, run_dir, options, context.Progress());
  context.FinishProgress();
  for (const std::string& warning : result.warnings) context.Warn(warning);
  if (result.visual_odometry) {
    std::printf(
        "wrote %s: %zu of %zu frames tracked, %zu key frames, %zu segments, %.2f s "
        "(%.0f frames/s)\n",
        run_dir.c_str(), result.visual.tracked, result.visual.frames, result.visual.key_frames,
        result.visual.segments, result.run_time_s, result.scans_per_s);
    return;
  }
  std::printf(
      "wrote %s: %zu poses, %zu key frames, loops %zu accepted / %zu rejected, %.2f s "
      "(%.0f scans/s)\n",
      run_dir.c_str(), result.poses, result.key_frames, result.loops_accepted,
      result.loops_rejected, result.run_time_s, result.scans_per_s);
}

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

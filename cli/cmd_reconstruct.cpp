// littermap reconstruct BAG -o RUN_DIR [--topic ROLE=T]... [--stamps header|recorded]
// Trajectory, occupancy map and quality of a run (DESIGN.md, "The command line").

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "cli/sensor_arguments.hpp"
#include "run/reconstruct_run.hpp"

namespace littermap::cli {
namespace {

struct ReconstructArguments {
  std::string bag;
  std::string run_dir;
  std::string scan_topic, odometry_topic;  // the older way to name the two roles
  SensorArguments sensors;
  run::ReconstructRunOptions options;
};

void RunReconstruct(ReconstructArguments arguments, CliContext& context) {
  arguments.options.topic_roles = arguments.sensors.Roles();
  if (!arguments.scan_topic.empty()) arguments.options.topic_roles["scan"] = arguments.scan_topic;
  if (!arguments.odometry_topic.empty()) {
    arguments.options.topic_roles["odometry"] = arguments.odometry_topic;
  }
  arguments.options.reconstruction.stamps = arguments.sensors.Stamps();
  const run::ReconstructRunResult result =
      run::ReconstructRun(arguments.bag, arguments.run_dir, arguments.options, context.Progress());
  context.FinishProgress();
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::printf("%s\n", run::ReconstructSummary(result).c_str());
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
      ->check(ExistingInput(InputKind::kFileOrFolder));
  command->add_option("-o,--output", arguments->run_dir, "Run directory to write")->required();
  command->add_flag("--force", arguments->options.force_output,
                    "Write into an output folder that holds files littermap does not write there");
  reconstruct::ReconstructionOptions& options = arguments->options.reconstruction;
  command->add_option("--scan-topic", arguments->scan_topic, "LaserScan topic (= --topic scan=T)");
  command->add_option("--odom-topic", arguments->odometry_topic,
                      "Odometry topic (= --topic odometry=T)");
  AddSensorOptions(command, arguments->sensors);
  command
      ->add_option("--options", arguments->options.options_file,
                   "YAML file of tuning options (unknown keys are errors)")
      ->check(ExistingInput(InputKind::kFile));
  command->add_flag("--no-loop-closure{false}", options.slam.loop_closure,
                    "Track and map without loop closure (for comparisons)");
  command->add_flag("--no-rgbd{false}", options.rgbd,
                    "Track with the laser alone, without the RGB-D routine (for comparisons)");
  command->add_flag("--no-gyro{false}", options.gyro_heading,
                    "Turn the odometry by the wheels alone, not by the IMU's yaw rate (for "
                    "comparisons)");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunReconstruct(*arguments, context); };
  });
}

}  // namespace littermap::cli

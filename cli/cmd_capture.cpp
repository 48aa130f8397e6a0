// littermap capture [--camera URI] [--laser URI] [--odometry URI] -o BAG [--robot ROBOT.yaml]
//                   [--duration S] [--camera-mode WxH@FPS] [--min-free-disk-mb N]
//                   [--truth DIR] [--seed N] [--run-seed N] [--route NAME] [--contact-sheet PNG]
// Records a run from the robot's sensors (capture/live_capture.hpp): an OpenNI2 RGB-D camera, a
// SCIP 2.0 laser and the base's wheel odometry, each optional; or from the park simulator when
// the sources are sim:WORLD.yaml. SIGINT and SIGTERM finish the bag; a second one kills.

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "capture/live_capture.hpp"
#include "cli/option_checks.hpp"
#include "cli/simulate_run.hpp"
#include "cli/stop_on_signals.hpp"
#include "core/error.hpp"

namespace littermap::cli {
namespace {

struct CaptureArguments {
  capture::LiveCaptureOptions live;
  bool list_cameras = false;
  SimulateRequest simulate;  // -o, --duration and the sim: options
};

void RequireNoSimulatorOptions(const SimulateRequest& simulate) {
  const sim::SimulateRunOptions& options = simulate.options;
  const std::pair<const char*, bool> sim_only[] = {
      {"--truth", !options.truth_dir.empty()},
      {"--route", !options.record.route.empty()},
      {"--contact-sheet", !options.contact_sheet_png.empty()}};
  for (const auto& [option, given] : sim_only) {
    if (given) throw UsageError(std::string(option) + " works with sim: sources only");
  }
  if (options.record.seed || options.record.run_seed) {
    throw UsageError("--seed and --run-seed work with sim: sources only");
  }
}

void RunCapture(CaptureArguments arguments, CliContext& context) {
  if (arguments.list_cameras) {
    const std::vector<std::string> devices = capture::Openni2Camera::ListDevices();
    for (const std::string& device : devices) std::printf("openni2:%s\n", device.c_str());
    if (devices.empty()) std::printf("no OpenNI2 device found\n");
    return;
  }
  SimulateRequest& simulate = arguments.simulate;
  if (simulate.bag.empty()) throw UsageError("--output is required");
  if (const auto world = capture::SimulatedWorld(arguments.live.sources)) {
    simulate.world = *world;
    RunSimulate(simulate, context);
    return;
  }
  RequireNoSimulatorOptions(simulate);
  arguments.live.storage = simulate.options.record.bag.storage;
  arguments.live.duration_s = simulate.options.duration_s;
  StopOnSignals signals;
  const capture::RecordingResult result = capture::CaptureLive(
      simulate.bag, arguments.live, signals.stop_requested(),
      [&context](const capture::RecorderStatus& status) {
        for (const std::string& event : status.new_events) context.Warn(event);
        context.Status(capture::FormatStatus(status));
      },
      [&context](const std::string& warning) { context.Warn(warning); });
  context.FinishProgress();
  std::fputs(capture::RecordingSummary(simulate.bag, result).c_str(), stdout);
  if (result.stop == capture::RecordingStop::kWriteFailed) {
    throw Error(result.failure_kind, simulate.bag + ": " + result.stop_reason +
                                         " (the bag keeps everything written before)");
  }
}

}  // namespace

void RegisterCaptureCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<CaptureArguments>();
  capture::LiveCaptureOptions& live = arguments->live;
  sim::SimulateRunOptions& simulate = arguments->simulate.options;
  CLI::App* capture = context.AddCommand(
      app, "capture",
      "Record a run from the robot's sensors (OpenNI2 RGB-D camera, SCIP 2.0 laser, wheel "
      "odometry) or from the park simulator (sim:WORLD.yaml)");
  capture->add_option("--camera", live.sources.camera_uri,
                      "RGB-D camera: openni2 (first device), openni2:DEVICE_URI, "
                      "sim:WORLD.yaml or none");
  capture->add_option("--laser", live.sources.laser_uri,
                      "Laser scanner: scip://HOST:PORT, scip:/dev/ttyACM0, sim:WORLD.yaml or none");
  capture->add_option("--odometry", live.sources.odometry_uri,
                      "Wheel odometry: tcp://HOST:PORT, serial:/dev/ttyUSB0 ($ODOM line "
                      "protocol), sim:WORLD.yaml or none");
  capture->add_option("-o,--output", arguments->simulate.bag, "Bag directory to create");
  capture->add_option("--robot", live.robot_yaml,
                      "Robot description YAML: sensor mounts on base_link, for /tf_static");
  capture
      ->add_option("--duration", simulate.duration_s,
                   "Stop after this many seconds (default: until SIGINT/SIGTERM)")
      ->check(FiniteRange(0.1, kMaxDurationS));
  capture
      ->add_option("--camera-mode", live.camera_mode,
                   "Camera mode WIDTHxHEIGHT@FPS; the nearest the device offers is used")
      ->capture_default_str();
  capture
      ->add_option("--min-free-disk-mb", live.min_free_disk_mb,
                   "Stop cleanly when the disk has less than this left")
      ->capture_default_str()
      ->check(FiniteRange(0, 1e9));
  capture->add_flag("--list-cameras", arguments->list_cameras, "List the OpenNI2 devices and exit");
  capture
      ->add_option("--storage", simulate.record.bag.storage,
                   "Bag storage: sqlite3 (rosbag2's default before Iron) or mcap")
      ->check(CLI::IsMember({"sqlite3", "mcap"}))
      ->capture_default_str();
  capture->add_option("--truth", simulate.truth_dir,
                      "sim: also write the ground truth into this directory");
  capture->add_option("--seed", simulate.record.seed, "sim: random seed")->check(Seed());
  capture
      ->add_option("--run-seed", simulate.record.run_seed,
                   "sim: seed of sensor noise only (the same park)")
      ->check(Seed());
  capture->add_option("--route", simulate.record.route, "sim: a named route of the world");
  capture
      ->add_option("--contact-sheet", simulate.contact_sheet_png,
                   "sim: also write a PNG of sampled colour, depth and laser frames")
      ->check(FileExtension({".png", ".jpg"}));
  capture->callback([arguments, &context] {
    context.run = [arguments, &context] { RunCapture(*arguments, context); };
  });
}

}  // namespace littermap::cli

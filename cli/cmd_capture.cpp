// littermap capture [--camera URI] [--laser URI] [--odometry URI] -o BAG [--robot ROBOT.yaml]
//                   [--duration S] [--camera-mode WxH@FPS] [--min-free-disk-mb N]
//                   [--truth DIR] [--seed N] [--run-seed N] [--route NAME] [--contact-sheet PNG]
// Records a run from the robot's sensors (capture/recorder.hpp): an OpenNI2 RGB-D camera, a
// SCIP 2.0 laser and the base's wheel odometry, each optional; or from the park simulator when
// the sources are sim:WORLD.yaml. SIGINT and SIGTERM finish the bag; a second one kills.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "capture/byte_stream.hpp"
#include "capture/odometry_source.hpp"
#include "capture/openni2_camera.hpp"
#include "capture/recorder.hpp"
#include "capture/robot_description.hpp"
#include "capture/scip_laser_source.hpp"
#include "cli/simulate_run.hpp"
#include "cli/stop_on_signals.hpp"
#include "core/error.hpp"

namespace littermap::cli {
namespace {

constexpr std::string_view kSimScheme = "sim:";

struct CaptureArguments {
  std::string camera, laser, odometry;
  std::string robot;
  std::string camera_mode = "640x480@30";
  double min_free_disk_mb = 256;
  bool list_cameras = false;
  SimulateRequest simulate;
};

bool IsSim(const std::string& uri) { return uri.starts_with(kSimScheme); }
bool IsNone(const std::string& uri) { return uri.empty() || uri == "none"; }

bool SameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  return std::filesystem::weakly_canonical(a, error) == std::filesystem::weakly_canonical(b, error);
}

// All given sources are sim:WORLD.yaml of one world (camera and laser both given).
void RunSimulatedCapture(CaptureArguments& arguments, CliContext& context) {
  const std::string world = arguments.camera.substr(kSimScheme.size());
  if (world.empty()) throw UsageError("--camera '" + arguments.camera + "' names no world file");
  const std::pair<const char*, const std::string*> others[] = {{"--laser", &arguments.laser},
                                                               {"--odometry", &arguments.odometry}};
  for (const auto& [option, uri] : others) {
    if (IsNone(*uri) && std::string(option) == "--odometry") continue;
    if (!IsSim(*uri) || !SameFile(uri->substr(kSimScheme.size()), world)) {
      throw UsageError(std::string(option) + " '" + *uri + "' and --camera '" + arguments.camera +
                       "' must simulate the same world (a simulated and a real sensor do not "
                       "record together)");
    }
  }
  arguments.simulate.world = world;
  RunSimulate(arguments.simulate, context);
}

void RunRealCapture(const CaptureArguments& arguments, CliContext& context) {
  const capture::Openni2CameraOptions camera_options =
      capture::ParseCameraMode(arguments.camera_mode);
  std::vector<std::unique_ptr<capture::SensorSource>> sources;
  if (!IsNone(arguments.camera)) {
    sources.push_back(std::make_unique<capture::Openni2Camera>(arguments.camera, camera_options));
  }
  if (!IsNone(arguments.laser))
    sources.push_back(std::make_unique<capture::ScipLaserSource>(arguments.laser));
  if (!IsNone(arguments.odometry)) {
    sources.push_back(std::make_unique<capture::OdometrySource>(arguments.odometry));
  }
  if (sources.empty()) {
    throw UsageError("nothing to record: give --camera, --laser or --odometry");
  }
  msg::TFMessage tf_static;
  if (!arguments.robot.empty()) {
    tf_static =
        capture::StaticTransforms(HostNowNs(), capture::ReadRobotDescription(arguments.robot));
  } else {
    context.Warn(
        "no --robot description: the bag has no /tf_static, and later stages place "
        "the sensors at base_link");
  }

  capture::RecorderOptions options;
  if (arguments.simulate.duration_s) {
    if (!(*arguments.simulate.duration_s > 0)) throw UsageError("--duration: must be positive");
    options.max_duration_s = *arguments.simulate.duration_s;
  }
  if (!(arguments.min_free_disk_mb >= 0)) throw UsageError("--min-free-disk-mb: must be >= 0");
  options.min_free_disk_bytes = static_cast<std::uint64_t>(arguments.min_free_disk_mb * 1048576.0);

  StopOnSignals signals;
  const capture::RecordingResult result =
      capture::Record(arguments.simulate.bag, std::move(sources), tf_static, options,
                      signals.stop_requested(), [&context](const capture::RecorderStatus& status) {
                        for (const std::string& event : status.new_events) context.Warn(event);
                        context.Status(capture::FormatStatus(status));
                      });
  context.FinishProgress();

  std::printf("%s: %s after %.1f s, %llu messages\n", arguments.simulate.bag.c_str(),
              result.stop_reason.c_str(), result.duration_s,
              static_cast<unsigned long long>(result.messages));
  for (const capture::SourceStatus& source : result.sources) {
    std::printf("  %s\n", capture::FormatSummary(source).c_str());
  }
  if (result.stop == capture::RecordingStop::kWriteFailed) {
    throw InternalError(arguments.simulate.bag + ": " + result.stop_reason +
                        " (the bag keeps everything written before)");
  }
}

void RunCapture(CaptureArguments arguments, CliContext& context) {
  if (arguments.list_cameras) {
    const std::vector<std::string> devices = capture::Openni2Camera::ListDevices();
    for (const std::string& device : devices) std::printf("openni2:%s\n", device.c_str());
    if (devices.empty()) std::printf("no OpenNI2 device found\n");
    return;
  }
  if (arguments.simulate.bag.empty()) throw UsageError("--output is required");
  const bool any_sim =
      IsSim(arguments.camera) || IsSim(arguments.laser) || IsSim(arguments.odometry);
  if (any_sim) {
    if (!IsSim(arguments.camera)) {
      throw UsageError("--camera '" + arguments.camera +
                       "': a simulated capture needs --camera sim:WORLD.yaml as well");
    }
    RunSimulatedCapture(arguments, context);
    return;
  }
  const std::pair<const char*, const std::string*> sim_only[] = {
      {"--truth", &arguments.simulate.truth},
      {"--route", &arguments.simulate.route},
      {"--contact-sheet", &arguments.simulate.contact_sheet}};
  for (const auto& [option, value] : sim_only) {
    if (!value->empty()) throw UsageError(std::string(option) + " works with sim: sources only");
  }
  if (arguments.simulate.seed || arguments.simulate.run_seed) {
    throw UsageError("--seed and --run-seed work with sim: sources only");
  }
  RunRealCapture(arguments, context);
}

}  // namespace

void RegisterCaptureCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<CaptureArguments>();
  CLI::App* capture = context.AddCommand(
      app, "capture",
      "Record a run from the robot's sensors (OpenNI2 RGB-D camera, SCIP 2.0 laser, wheel "
      "odometry) or from the park simulator (sim:WORLD.yaml)");
  capture->add_option("--camera", arguments->camera,
                      "RGB-D camera: openni2 (first device), openni2:DEVICE_URI, "
                      "sim:WORLD.yaml or none");
  capture->add_option("--laser", arguments->laser,
                      "Laser scanner: scip://HOST:PORT, scip:/dev/ttyACM0, sim:WORLD.yaml or none");
  capture->add_option("--odometry", arguments->odometry,
                      "Wheel odometry: tcp://HOST:PORT, serial:/dev/ttyUSB0 ($ODOM line "
                      "protocol), sim:WORLD.yaml or none");
  capture->add_option("-o,--output", arguments->simulate.bag, "Bag directory to create");
  capture->add_option("--robot", arguments->robot,
                      "Robot description YAML: sensor mounts on base_link, for /tf_static");
  capture->add_option("--duration", arguments->simulate.duration_s,
                      "Stop after this many seconds (default: until SIGINT/SIGTERM)");
  capture
      ->add_option("--camera-mode", arguments->camera_mode,
                   "Camera mode WIDTHxHEIGHT@FPS; the nearest the device offers is used")
      ->capture_default_str();
  capture
      ->add_option("--min-free-disk-mb", arguments->min_free_disk_mb,
                   "Stop cleanly when the disk has less than this left")
      ->capture_default_str();
  capture->add_flag("--list-cameras", arguments->list_cameras, "List the OpenNI2 devices and exit");
  capture->add_option("--truth", arguments->simulate.truth,
                      "sim: also write the ground truth into this directory");
  capture->add_option("--seed", arguments->simulate.seed, "sim: random seed")
      ->check(CLI::NonNegativeNumber);
  capture
      ->add_option("--run-seed", arguments->simulate.run_seed,
                   "sim: seed of sensor noise only (the same park)")
      ->check(CLI::NonNegativeNumber);
  capture->add_option("--route", arguments->simulate.route, "sim: a named route of the world");
  capture->add_option("--contact-sheet", arguments->simulate.contact_sheet,
                      "sim: also write a PNG of sampled colour, depth and laser frames");
  capture->callback([arguments, &context] {
    context.run = [arguments, &context] { RunCapture(*arguments, context); };
  });
}

}  // namespace littermap::cli

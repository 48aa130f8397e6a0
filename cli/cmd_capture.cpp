// littermap capture --camera URI --laser URI [--odometry URI] -o BAG [--duration S]
//                   [--truth DIR] [--seed N] [--run-seed N] [--route NAME]
//                   [--contact-sheet FILE.png]
// Records a run. This version knows one source, the park simulator: sim:WORLD.yaml for every
// sensor, which makes it `littermap simulate` under the field crew's command. Real sensors
// (OpenNI2 RGB-D, SCIP laser) are named in the error so a script fails loudly.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/simulate_run.hpp"
#include "core/error.hpp"

namespace littermap::cli {
namespace {

constexpr std::string_view kSimScheme = "sim:";

struct CaptureArguments {
  std::string camera, laser, odometry;
  SimulateRequest simulate;
};

// The world file of a sim: source; a UsageError naming the option for anything else.
std::filesystem::path SimWorld(const std::string& option, const std::string& uri) {
  if (!uri.starts_with(kSimScheme) || uri.size() == kSimScheme.size()) {
    throw UsageError(option + " '" + uri +
                     "': this version captures only from the park simulator "
                     "(sim:WORLD.yaml); real sensor sources are not supported yet");
  }
  return uri.substr(kSimScheme.size());
}

bool SameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  return std::filesystem::weakly_canonical(a, error) == std::filesystem::weakly_canonical(b, error);
}

void RunCapture(CaptureArguments arguments, CliContext& context) {
  const std::filesystem::path world = SimWorld("--camera", arguments.camera);
  std::optional<std::pair<std::string, std::string>> others[] = {
      std::make_pair(std::string("--laser"), arguments.laser),
      arguments.odometry.empty()
          ? std::nullopt
          : std::optional(std::make_pair(std::string("--odometry"), arguments.odometry))};
  for (const auto& other : others) {
    if (!other) continue;
    if (!SameFile(SimWorld(other->first, other->second), world)) {
      throw UsageError(other->first + " '" + other->second + "' and --camera '" + arguments.camera +
                       "' must simulate the same world");
    }
  }
  arguments.simulate.world = world.string();
  RunSimulate(arguments.simulate, context);
}

}  // namespace

void RegisterCaptureCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<CaptureArguments>();
  CLI::App* capture =
      context.AddCommand(app, "capture",
                         "Record a run from the robot's sensors; this version: the park simulator "
                         "(--camera sim:WORLD.yaml --laser sim:WORLD.yaml)");
  capture->add_option("--camera", arguments->camera, "RGB-D camera source: sim:WORLD.yaml")
      ->required();
  capture->add_option("--laser", arguments->laser, "Laser scanner source: sim:WORLD.yaml")
      ->required();
  capture->add_option("--odometry", arguments->odometry,
                      "Wheel odometry source: sim:WORLD.yaml (default: the camera's)");
  capture->add_option("-o,--output", arguments->simulate.bag, "Bag directory to create")
      ->required();
  capture->add_option("--duration", arguments->simulate.duration_s, "Stop after this many seconds");
  capture->add_option("--truth", arguments->simulate.truth,
                      "sim: also write the ground truth into this directory");
  capture->add_option("--seed", arguments->simulate.seed, "sim: random seed");
  capture->add_option("--run-seed", arguments->simulate.run_seed,
                      "sim: seed of sensor noise only (the same park)");
  capture->add_option("--route", arguments->simulate.route, "sim: a named route of the world");
  capture->add_option("--contact-sheet", arguments->simulate.contact_sheet,
                      "Also write a PNG of sampled colour, depth and laser frames");
  capture->callback([arguments, &context] {
    context.run = [arguments, &context] { RunCapture(*arguments, context); };
  });
}

}  // namespace littermap::cli

// littermap detect BAG --run RUN_DIR [-o DIR] [--model MODEL] [--every N]
// Segments every n-th RGB-D frame, classifies the objects, places them with the run's
// trajectory and fuses the sightings into litter items: DIR/detections.csv and DIR/items.csv.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/debug_frames.hpp"
#include "cli/run_stages.hpp"
#include "run/detect_run.hpp"

namespace littermap::cli {
namespace {

struct DetectArguments {
  std::string bag;
  std::string run_dir;
  std::string output;
  std::string trajectory;
  std::string model = LITTERMAP_DEFAULT_MODEL;
  std::string debug_frames;
  detect::RunObjectsOptions objects;
  detect::FusionOptions fusion;
};

void RunDetect(const DetectArguments& arguments, CliContext& context) {
  run::DetectRunOptions options;
  options.model = arguments.model;
  options.trajectory = arguments.trajectory;
  options.output_dir = arguments.output;
  options.objects = arguments.objects;
  options.fusion = arguments.fusion;
  DetectStage(arguments.bag, arguments.run_dir, options, context, arguments.debug_frames);
}

}  // namespace

void DetectStage(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                 const run::DetectRunOptions& options, CliContext& context,
                 const std::filesystem::path& debug_frames) {
  if (!debug_frames.empty()) std::filesystem::create_directories(debug_frames);
  const run::DetectRunResult result = run::DetectRun(
      bag, run_dir, options, context.Progress(),
      [&](const detect::RgbdFrame& frame, const detect::FrameSegmentation& segmentation) {
        if (!debug_frames.empty()) WriteDebugFrame(debug_frames, frame, segmentation);
      });
  context.FinishProgress();
  if (result.objects.frames_without_pose > 0) {
    context.Warn(std::to_string(result.objects.frames_without_pose) +
                 " frames lay outside the trajectory and were skipped");
  }
  std::printf(
      "wrote %s: %zu frames, %zu objects, %zu litter items and %zu natural objects seen in >= %d "
      "views\n%s\n",
      result.output_dir.c_str(), result.objects.frames, result.objects.objects, result.litter_items,
      result.natural_objects, options.fusion.min_views,
      SegmentationTimeLine(result.objects).c_str());
}

void RegisterDetectCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<DetectArguments>();
  CLI::App* command = context.AddCommand(
      app, "detect",
      "Detect and classify litter in a run's RGB-D frames: RUN_DIR/detections.csv (per frame) "
      "and RUN_DIR/items.csv (fused items)");
  command->add_option("BAG", arguments->bag, "Run bag directory")
      ->required()
      ->check(CLI::ExistingPath);
  command->add_option("--run", arguments->run_dir, "Run directory of `littermap reconstruct`")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("-o,--output", arguments->output,
                      "Where to write (default: the run directory)");
  command
      ->add_option("--trajectory", arguments->trajectory,
                   "TUM trajectory to place objects with (default RUN_DIR/trajectory.tum; "
                   "e.g. the simulator's truth)")
      ->check(CLI::ExistingFile);
  command->add_option("--model", arguments->model, "Classifier model of `littermap train`")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command->add_option("--every", arguments->objects.every, "Process every n-th frame")
      ->capture_default_str();
  command
      ->add_option("--min-views", arguments->fusion.min_views,
                   "Frames an item must be seen in to be kept")
      ->capture_default_str();
  command
      ->add_option("--association-radius", arguments->fusion.association_radius_m,
                   "Sightings this close (m) are one item")
      ->capture_default_str();
  command->add_option("--debug-frames", arguments->debug_frames,
                      "Write a segmentation picture of every processed frame here");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunDetect(*arguments, context); };
  });
}

}  // namespace littermap::cli

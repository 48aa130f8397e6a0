// littermap detect: the detect stage of a run (run/detect_run.hpp)

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "cli/sensor_arguments.hpp"
#include "detect/debug_frames.hpp"
#include "detect/options_file.hpp"
#include "run/detect_run.hpp"

namespace littermap::cli {
namespace {

void DetectStage(const std::filesystem::path& bag, const std::filesystem::path& run_dir,
                 const run::DetectRunOptions& options, CliContext& context,
                 const std::filesystem::path& debug_frames) {
  const run::DetectRunResult result = run::DetectRun(bag, run_dir, options, context.Progress(),
                                                     detect::DebugFrameWriter(debug_frames));
  context.FinishProgress();
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::printf("%s\n", run::DetectSummary(result, options.fusion).c_str());
}

}  // namespace

void RegisterDetectCommand(CLI::App& app, CliContext& context) {
  struct DetectArguments {
    std::string bag;
    std::string run_dir;
    std::string debug_frames;
    std::string options_file;
    SensorArguments sensors;
    run::DetectRunOptions options;
  };
  auto arguments = std::make_shared<DetectArguments>();
  arguments->options.model = LITTERMAP_DEFAULT_MODEL;
  CLI::App* command = context.AddCommand(
      app, "detect",
      "Detect and classify litter in a run's RGB-D frames: RUN_DIR/detections.csv (per frame) "
      "and RUN_DIR/items.csv (fused items)");
  command->add_option("BAG", arguments->bag, "Run bag directory")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  command->add_option("--run", arguments->run_dir, "Run directory of `littermap reconstruct`")
      ->required()
      ->check(ExistingInput(InputKind::kFolder));
  command->add_option("-o,--output", arguments->options.output_dir,
                      "Where to write (default: the run directory)");
  command->add_flag("--force", arguments->options.force_output,
                    "Write into an output folder that holds files littermap does not write there");
  command
      ->add_option("--trajectory", arguments->options.trajectory,
                   "TUM trajectory to place objects with (default RUN_DIR/trajectory.tum; "
                   "e.g. the simulator's truth)")
      ->check(ExistingInput(InputKind::kFile));
  command->add_option("--model", arguments->options.model, "Classifier model of `littermap train`")
      ->capture_default_str()
      ->check(ExistingInput(InputKind::kFile));
  command->add_option("--every", arguments->options.objects.every, "Process every n-th frame")
      ->capture_default_str()
      ->check(WholeNumber<std::size_t>(1, kMaxFrameStep));
  command
      ->add_option("--min-views", arguments->options.fusion.min_views,
                   "Frames an item must be seen in to be kept")
      ->capture_default_str()
      ->check(WholeNumber(1, 1000));
  command
      ->add_option("--min-seen-share", arguments->options.fusion.min_seen_share,
                   "Share of the frames that could see an item it must be seen in to be kept")
      ->capture_default_str()
      ->check(FiniteRange(0, 1));
  command
      ->add_option("--association-radius", arguments->options.fusion.association_radius_m,
                   "Sightings this close (m) are one item")
      ->capture_default_str()
      ->check(FiniteRange(0.01, 10));
  command
      ->add_option("--options", arguments->options_file,
                   "YAML file of tuning options (unknown keys are errors; the flags above "
                   "override it)")
      ->check(ExistingInput(InputKind::kFile));
  command->add_option("--debug-frames", arguments->debug_frames,
                      "Write a segmentation picture of every processed frame here");
  AddSensorOptions(command, arguments->sensors);
  command->callback([arguments, command, &context] {
    if (!arguments->options_file.empty()) {
      // The file sets the tuning; a flag given on the command line overrides it.
      const run::DetectRunOptions flags = arguments->options;
      run::DetectRunOptions& options = arguments->options;
      detect::ApplyOptionsFile(arguments->options_file, &options.objects, &options.fusion);
      if (command->count("--every") > 0) options.objects.every = flags.objects.every;
      if (command->count("--min-views") > 0) options.fusion.min_views = flags.fusion.min_views;
      if (command->count("--min-seen-share") > 0) {
        options.fusion.min_seen_share = flags.fusion.min_seen_share;
      }
      if (command->count("--association-radius") > 0) {
        options.fusion.association_radius_m = flags.fusion.association_radius_m;
      }
    }
    context.run = [arguments, &context] {
      arguments->options.topic_roles = arguments->sensors.Roles();
      arguments->options.objects.frames.stamps = arguments->sensors.Stamps();
      DetectStage(arguments->bag, arguments->run_dir, arguments->options, context,
                  arguments->debug_frames);
    };
  });
}

}  // namespace littermap::cli

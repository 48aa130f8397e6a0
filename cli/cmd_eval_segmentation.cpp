// littermap eval segmentation (detect/segmentation_evaluation.hpp)

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "detect/options_file.hpp"
#include "detect/segmentation_evaluation.hpp"

namespace littermap::cli {
namespace {

struct SegmentationArguments {
  std::string bag;
  std::string truth_dir;
  bool json = false;
  std::string options_file;
  detect::SegmentationEvaluationOptions options;
};

void RunEvalSegmentation(const SegmentationArguments& arguments, CliContext& context) {
  const detect::SegmentationEvaluation evaluation = detect::EvaluateSegmentation(
      arguments.bag, arguments.truth_dir, arguments.options, context.Progress());
  context.FinishProgress();
  std::printf("%s\n", arguments.json ? detect::ToJson(evaluation).c_str()
                                     : detect::ToText(evaluation).c_str());
}

}  // namespace

void RegisterEvalSegmentationCommand(CLI::App& app, CliContext& context) {
  CLI::App* eval_command = app.get_subcommand("eval");
  auto arguments = std::make_shared<SegmentationArguments>();
  CLI::App* command = context.AddCommand(
      *eval_command, "segmentation",
      "Segmentation IoU of litter and natural objects on a simulated run's instance masks "
      "(objects in view and within the depth range; 'objects' counts object-frame pairs)");
  command->add_option("BAG", arguments->bag, "Run bag of `littermap simulate`")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  command->add_option("TRUTH_DIR", arguments->truth_dir, "Its ground truth")
      ->required()
      ->check(ExistingInput(InputKind::kFolder));
  command
      ->add_option("--min-pixels", arguments->options.min_depth_pixels,
                   "Score objects showing at least this many pixels with depth")
      ->capture_default_str()
      ->check(WholeNumber(0, 100000000));
  command
      ->add_option("--options", arguments->options_file,
                   "YAML file of detection tuning options, as for `detect --options`")
      ->check(ExistingInput(InputKind::kFile));
  command->add_flag("--json", arguments->json,
                    "JSON: {CLASS: {objects, mean_iou, found_share}}, CLASS 'all' too");
  command->callback([arguments, &context] {
    if (!arguments->options_file.empty()) {
      detect::RunObjectsOptions objects;
      detect::FusionOptions fusion;
      detect::ApplyOptionsFile(arguments->options_file, &objects, &fusion);
      arguments->options.segmentation = objects.segmentation;
    }
    context.run = [arguments, &context] { RunEvalSegmentation(*arguments, context); };
  });
}

}  // namespace littermap::cli

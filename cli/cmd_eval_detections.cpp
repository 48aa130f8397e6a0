// littermap eval detections (eval/detection_evaluation.hpp)

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/object_classes.hpp"
#include "eval/detection_evaluation.hpp"
#include "run/items_file.hpp"

namespace littermap::cli {
namespace {

struct DetectionArguments {
  std::string items;
  std::string truth;
  std::string natural;
  std::string visible;
  std::vector<std::string> align;  // EST.tum REF.tum
  bool json = false;
  eval::DetectionMetricsOptions options;
};

void RunDetections(const DetectionArguments& arguments) {
  const eval::DetectionTruth truth =
      eval::ReadDetectionTruth(arguments.truth, arguments.natural, arguments.visible);
  // Without a litter column an item is litter unless its class is a natural one.
  std::vector<eval::DetectedItem> items;
  for (const run::ItemRow& row : run::ReadItemsCsv(arguments.items)) {
    const bool litter = row.litter.value_or(!IsNaturalClass(row.class_name));
    items.push_back({row.id, row.class_name, {row.x_m, row.y_m}, row.confidence, litter});
  }
  if (!arguments.align.empty())
    items = eval::AlignItems(std::move(items), arguments.align[0], arguments.align[1]);
  const eval::DetectionMetrics metrics = eval::EvaluateDetections(items, truth, arguments.options);
  std::printf("%s\n", arguments.json ? eval::ToJson(metrics, arguments.options).c_str()
                                     : eval::ToText(metrics, arguments.options).c_str());
}

}  // namespace

void RegisterEvalDetectionsCommand(CLI::App& app, CliContext& context) {
  CLI::App& eval_command = *app.get_subcommand("eval");
  auto arguments = std::make_shared<DetectionArguments>();
  CLI::App* detections = context.AddCommand(
      eval_command, "detections",
      "Litter precision, recall and F1, a per-class table and a confusion matrix of detected "
      "items against the simulator's truth, matched one-to-one within a radius");
  // No ExistingFile checks: an unreadable file is bad input (exit 2) and the readers say so.
  detections->add_option("ITEMS", arguments->items, "Detected items (items.csv)")->required();
  detections->add_option("TRUTH", arguments->truth, "Truth litter (the simulator's litter.csv)")
      ->required();
  detections->add_option("--natural", arguments->natural,
                         "Natural look-alikes (the simulator's natural.csv), for the confusion "
                         "matrix and litter/natural accuracy");
  CLI::Option* visible = detections->add_option(
      "--visible", arguments->visible,
      "The simulator's masks/visible.csv: only objects shown with --min-pixels count as truth");
  detections
      ->add_option("--min-pixels", arguments->options.min_visible_pixels,
                   "Pixels an object must cover in some masked frame to count as truth")
      ->capture_default_str()
      ->check(WholeNumber<std::size_t>(0, 100000000))
      ->needs(visible);
  detections
      ->add_option("--match-radius", arguments->options.match_radius_m,
                   "Largest distance of a matched item and truth object, metres")
      ->capture_default_str()
      ->check(FiniteRange(0.01, 100));
  detections
      ->add_option("--min-confidence", arguments->options.min_confidence,
                   "Leave out items less sure than this (items.csv confidence, 0 to 1), as "
                   "`report` and `heatmap` do")
      ->capture_default_str()
      ->check(FiniteRange(0, 1));
  detections
      ->add_option("--align", arguments->align,
                   "EST.tum REF.tum: carry the items into the truth's frame by the rigid alignment "
                   "of the run's trajectory onto the reference trajectory (as ATE aligns them)")
      ->expected(2);
  detections->add_flag("--json", arguments->json,
                       "JSON output (precision, recall, f1, per_class, confusion, ...)");
  detections->callback(
      [arguments, &context] { context.run = [arguments] { RunDetections(*arguments); }; });
}

}  // namespace littermap::cli

// littermap eval detections ITEMS.csv TRUTH.csv [--natural NATURAL.csv]
//     [--visible VISIBLE.csv [--min-pixels N]] [--align EST.tum REF.tum] [--match-radius M]
//     [--json]
// Litter precision, recall, per-class table and confusion (eval/detection_metrics.hpp).

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "eval/detection_metrics.hpp"
#include "eval/trajectory_metrics.hpp"
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

// A run's items.csv as the metrics take them: without a litter column an item is litter unless
// its class is a natural one.
std::vector<eval::DetectedItem> ReadItems(const std::string& file) {
  std::vector<eval::DetectedItem> items;
  for (const run::ItemRow& row : run::ReadItemsCsv(file)) {
    items.push_back({row.id,
                     row.class_name,
                     {row.x_m, row.y_m},
                     row.confidence,
                     row.litter.value_or(!IsNaturalClass(row.class_name))});
  }
  return items;
}

// Items of a run placed in its own map frame, carried into the truth's frame by the rigid
// alignment of the run's trajectory onto the reference (the one ATE uses).
std::vector<eval::DetectedItem> AlignItems(std::vector<eval::DetectedItem> items,
                                           const std::vector<std::string>& align) {
  if (align.empty()) return items;
  const eval::TrajectoryMetrics metrics =
      eval::EvaluateTrajectory(bag::ReadTumTrajectory(align[0]), bag::ReadTumTrajectory(align[1]),
                               eval::TrajectoryMetricsOptions{});
  return eval::TransformItems(std::move(items), metrics.T_reference_estimate);
}

void PrintDetectionTables(const eval::DetectionMetrics& metrics) {
  std::printf("\n%-16s %6s %9s %5s %10s %7s\n", "class", "truth", "detected", "tp", "precision",
              "recall");
  for (const eval::ClassMetrics& c : metrics.per_class) {
    std::printf("%-16s %6zu %9zu %5zu %10.3f %7.3f\n", c.class_name.c_str(), c.truth, c.detected,
                c.true_positives, c.precision, c.recall);
  }
  std::printf("\nconfusion (rows: truth, columns: predicted)\n%-16s", "");
  const auto& labels = metrics.confusion_labels;
  for (const std::string& label : labels) {
    std::printf(" %*s", static_cast<int>(std::max<std::size_t>(label.size(), 4)), label.c_str());
  }
  for (std::size_t t = 0; t < labels.size(); ++t) {
    std::printf("\n%-16s", labels[t].c_str());
    for (std::size_t p = 0; p < labels.size(); ++p) {
      std::printf(" %*zu", static_cast<int>(std::max<std::size_t>(labels[p].size(), 4)),
                  metrics.confusion[t][p]);
    }
  }
  std::printf("\n");
}

void RunDetections(const DetectionArguments& arguments) {
  std::vector<eval::TruthObject> truth = eval::ReadTruthObjects(arguments.truth, true);
  if (!arguments.natural.empty()) {
    const auto natural = eval::ReadTruthObjects(arguments.natural, false);
    truth.insert(truth.end(), natural.begin(), natural.end());
  }
  std::optional<eval::VisiblePixels> visible;
  if (!arguments.visible.empty()) visible = eval::ReadVisiblePixels(arguments.visible);
  const eval::DetectionMetrics metrics = eval::EvaluateDetections(
      AlignItems(ReadItems(arguments.items), arguments.align), truth, arguments.options, visible);
  if (arguments.json) {
    std::printf("%s\n", eval::ToJson(metrics, arguments.options).c_str());
    return;
  }
  std::printf("matching           one-to-one within %.2f m, nearest pairs first\n",
              arguments.options.match_radius_m);
  std::printf("truth litter       %zu\n", metrics.truth_litter);
  if (visible) {
    std::printf("hidden objects     %zu (under %zu pixels in every mask: not truth)\n",
                metrics.hidden_truth, arguments.options.min_visible_pixels);
  }
  std::printf("detected litter    %zu\n", metrics.detected_litter);
  if (metrics.ignored_detections > 0) {
    std::printf("ignored detections %zu (at hidden litter, not scored)\n",
                metrics.ignored_detections);
  }
  std::printf("true positives     %zu\n", metrics.true_positives);
  std::printf("false positives    %zu\n", metrics.false_positives);
  std::printf("false negatives    %zu\n", metrics.false_negatives);
  std::printf("precision          %.3f\n", metrics.precision);
  std::printf("recall             %.3f\n", metrics.recall);
  std::printf("F1                 %.3f\n", metrics.f1);
  std::printf("class accuracy     %.3f over %zu true positives\n", metrics.class_accuracy,
              metrics.true_positives);
  std::printf("litter/natural     %.3f over %zu matched pairs of all items\n",
              metrics.litter_natural_accuracy, metrics.litter_natural_pairs);
  PrintDetectionTables(metrics);
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
      ->needs(visible);
  detections
      ->add_option("--match-radius", arguments->options.match_radius_m,
                   "Largest distance of a matched item and truth object, metres")
      ->capture_default_str();
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

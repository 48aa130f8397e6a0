#include "eval/detection_evaluation.hpp"

#include <algorithm>
#include <utility>

#include "eval/text_format.hpp"
#include "eval/trajectory_metrics.hpp"

namespace littermap::eval {
namespace {

void AppendTables(std::string& text, const DetectionMetrics& metrics) {
  AppendFormat(text, "\n%-16s %6s %9s %5s %10s %7s\n", "class", "truth", "detected", "tp",
               "precision", "recall");
  for (const ClassMetrics& c : metrics.per_class) {
    AppendFormat(text, "%-16s %6zu %9zu %5zu %10.3f %7.3f\n", c.class_name.c_str(), c.truth,
                 c.detected, c.true_positives, c.precision, c.recall);
  }
  AppendFormat(text, "\nconfusion (rows: truth, columns: predicted)\n%-16s", "");
  const auto& labels = metrics.confusion_labels;
  const auto width = [](const std::string& label) {
    return static_cast<int>(std::max<std::size_t>(label.size(), 4));
  };
  for (const std::string& label : labels) AppendFormat(text, " %*s", width(label), label.c_str());
  for (std::size_t t = 0; t < labels.size(); ++t) {
    AppendFormat(text, "\n%-16s", labels[t].c_str());
    for (std::size_t p = 0; p < labels.size(); ++p) {
      AppendFormat(text, " %*zu", width(labels[p]), metrics.confusion[t][p]);
    }
  }
  text += '\n';
}

}  // namespace

DetectionTruth ReadDetectionTruth(const std::filesystem::path& litter,
                                  const std::filesystem::path& natural,
                                  const std::filesystem::path& visible) {
  DetectionTruth truth;
  truth.objects = ReadTruthObjects(litter, true);
  if (!natural.empty()) {
    const std::vector<TruthObject> more = ReadTruthObjects(natural, false);
    truth.objects.insert(truth.objects.end(), more.begin(), more.end());
  }
  if (!visible.empty()) truth.visible_pixels = ReadVisiblePixels(visible);
  return truth;
}

std::vector<DetectedItem> AlignItems(std::vector<DetectedItem> items,
                                     const std::filesystem::path& estimate,
                                     const std::filesystem::path& reference) {
  const TrajectoryMetrics metrics =
      EvaluateTrajectory(estimate, reference, TrajectoryMetricsOptions{});
  return TransformItems(std::move(items), metrics.T_reference_estimate);
}

DetectionMetrics EvaluateDetections(const std::vector<DetectedItem>& detected,
                                    const DetectionTruth& truth,
                                    const DetectionMetricsOptions& options) {
  return EvaluateDetections(detected, truth.objects, options, truth.visible_pixels);
}

std::string ToText(const DetectionMetrics& metrics, const DetectionMetricsOptions& options) {
  std::string text;
  AppendFormat(text, "matching           one-to-one within %.2f m, nearest pairs first\n",
               options.match_radius_m);
  AppendFormat(text, "truth litter       %zu\n", metrics.truth_litter);
  if (metrics.visibility_filtered) {
    AppendFormat(text, "hidden objects     %zu (under %zu pixels in every mask: not truth)\n",
                 metrics.hidden_truth, options.min_visible_pixels);
  }
  if (options.min_confidence > 0) {
    AppendFormat(text, "below confidence   %zu items under %.2f (left out)\n",
                 metrics.below_confidence, options.min_confidence);
  }
  AppendFormat(text, "detected litter    %zu\n", metrics.detected_litter);
  if (metrics.ignored_detections > 0) {
    AppendFormat(text, "ignored detections %zu (at hidden litter, not scored)\n",
                 metrics.ignored_detections);
  }
  AppendFormat(text, "true positives     %zu\n", metrics.true_positives);
  AppendFormat(text, "false positives    %zu\n", metrics.false_positives);
  AppendFormat(text, "false negatives    %zu\n", metrics.false_negatives);
  AppendFormat(text, "precision          %.3f\n", metrics.precision);
  AppendFormat(text, "recall             %.3f\n", metrics.recall);
  if (!metrics.recall_by_masks.empty()) {
    text += "  by masks seen in ";
    for (const RecallByMasks& bucket : metrics.recall_by_masks) {
      AppendFormat(text, "  %s: %zu/%zu %.3f", bucket.masks.c_str(), bucket.true_positives,
                   bucket.truth, bucket.recall);
    }
    text += '\n';
  }
  AppendFormat(text, "F1                 %.3f\n", metrics.f1);
  AppendFormat(text, "class accuracy     %.3f over %zu true positives\n", metrics.class_accuracy,
               metrics.true_positives);
  AppendFormat(text, "litter/natural     %.3f over %zu matched pairs of all items\n",
               metrics.litter_natural_accuracy, metrics.litter_natural_pairs);
  AppendTables(text, metrics);
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::eval

#include "eval/detection_metrics.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/csv_table.hpp"
#include "core/error.hpp"

namespace littermap::eval {
namespace {

constexpr std::size_t kUnmatched = std::numeric_limits<std::size_t>::max();

std::size_t Count(const CsvRow& row, const std::string& column) {
  const std::string& text = row.Text(column);
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    row.Fail(column, "is not a non-negative integer: '" + text + "'");
  }
  return value;
}

double Ratio(std::size_t numerator, std::size_t denominator) {
  return denominator == 0 ? 1.0 : static_cast<double>(numerator) / static_cast<double>(denominator);
}

// For each item the index into `objects` it matched, or kUnmatched.
std::vector<std::size_t> Match(const std::vector<const DetectedItem*>& items,
                               const std::vector<const TruthObject*>& objects, double radius_m) {
  std::vector<Eigen::Vector2d> a, b;
  for (const DetectedItem* item : items) a.push_back(item->position_m);
  for (const TruthObject* object : objects) b.push_back(object->position_m);
  std::vector<std::size_t> matched(items.size(), kUnmatched);
  for (const auto& [i, j] : MatchByDistance(a, b, radius_m)) matched[i] = j;
  return matched;
}

// The items no object matched, and how many of them match one of `fallback` (hidden objects).
std::pair<std::vector<const DetectedItem*>, std::size_t> SplitUnmatched(
    const std::vector<const DetectedItem*>& items, const std::vector<std::size_t>& matched,
    const std::vector<const TruthObject*>& fallback, double radius_m) {
  std::vector<const DetectedItem*> unmatched;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (matched[i] == kUnmatched) unmatched.push_back(items[i]);
  }
  const auto on_fallback = Match(unmatched, fallback, radius_m);
  std::vector<const DetectedItem*> rest;
  for (std::size_t i = 0; i < unmatched.size(); ++i) {
    if (on_fallback[i] == kUnmatched) rest.push_back(unmatched[i]);
  }
  return {rest, unmatched.size() - rest.size()};
}

std::vector<ClassMetrics> CountPerClass(const std::vector<const DetectedItem*>& scored,
                                        const std::vector<const TruthObject*>& truth,
                                        const std::vector<const DetectedItem*>& predicted,
                                        const std::vector<std::size_t>& matched) {
  std::set<std::string> extra;
  for (const TruthObject* object : truth) extra.insert(object->class_name);
  for (const DetectedItem* item : predicted) extra.insert(item->class_name);
  for (const std::string& name : LitterClasses()) extra.erase(name);
  extra.erase("natural");
  extra.erase("none");
  std::vector<ClassMetrics> classes;
  for (const auto& name : LitterClasses()) classes.push_back({name});
  for (const auto& name : extra) classes.push_back({name});
  for (ClassMetrics& c : classes) {
    for (const TruthObject* object : truth) c.truth += object->class_name == c.class_name;
    for (const DetectedItem* item : scored) c.detected += item->class_name == c.class_name;
    for (std::size_t i = 0; i < predicted.size(); ++i) {
      c.true_positives += matched[i] != kUnmatched && predicted[i]->class_name == c.class_name &&
                          truth[matched[i]]->class_name == c.class_name;
    }
    c.precision = Ratio(c.true_positives, c.detected);
    c.recall = Ratio(c.true_positives, c.truth);
  }
  return classes;
}

// The masks an object has at least min_pixels in.
std::size_t MasksSeen(const VisiblePixels& visible, const std::string& id, std::size_t min_pixels) {
  const auto it = visible.find(id);
  if (it == visible.end()) return 0;
  return static_cast<std::size_t>(
      std::count_if(it->second.begin(), it->second.end(),
                    [&](std::size_t pixels) { return pixels >= min_pixels; }));
}

std::vector<RecallByMasks> CountRecallByMasks(const std::vector<const TruthObject*>& truth,
                                              const std::vector<bool>& found,
                                              const VisiblePixels& visible,
                                              std::size_t min_pixels) {
  std::vector<RecallByMasks> buckets = {{"1"}, {"2"}, {"3+"}};
  for (std::size_t j = 0; j < truth.size(); ++j) {
    // Visible truth was seen in at least one mask.
    const std::size_t masks = MasksSeen(visible, truth[j]->id, min_pixels);
    RecallByMasks& bucket = buckets[std::clamp<std::size_t>(masks, 1, 3) - 1];
    ++bucket.truth;
    bucket.true_positives += found[j];
  }
  for (RecallByMasks& bucket : buckets) bucket.recall = Ratio(bucket.true_positives, bucket.truth);
  return buckets;
}

// Litter scores: predicted litter against visible truth litter.
void ScoreLitter(const std::vector<DetectedItem>& detected,
                 const std::vector<const TruthObject*>& shown,
                 const std::vector<const TruthObject*>& hidden, double radius_m,
                 const std::optional<VisiblePixels>& visible, std::size_t min_pixels,
                 DetectionMetrics& metrics) {
  std::vector<const DetectedItem*> predicted;
  for (const DetectedItem& item : detected) {
    if (item.litter) predicted.push_back(&item);
  }
  std::vector<const TruthObject*> truth, hidden_litter;
  for (const TruthObject* object : shown) {
    if (object->litter) truth.push_back(object);
  }
  for (const TruthObject* object : hidden) {
    if (object->litter) hidden_litter.push_back(object);
  }
  const auto matched = Match(predicted, truth, radius_m);
  const auto [false_positives, ignored] =
      SplitUnmatched(predicted, matched, hidden_litter, radius_m);
  std::vector<const DetectedItem*> scored;
  std::vector<bool> found(truth.size(), false);
  std::size_t class_correct = 0;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (matched[i] == kUnmatched) continue;
    scored.push_back(predicted[i]);
    found[matched[i]] = true;
    class_correct += predicted[i]->class_name == truth[matched[i]]->class_name;
  }
  metrics.true_positives = scored.size();
  scored.insert(scored.end(), false_positives.begin(), false_positives.end());
  metrics.truth_litter = truth.size();
  metrics.detected_litter = scored.size();
  metrics.false_positives = false_positives.size();
  metrics.false_negatives = truth.size() - metrics.true_positives;
  metrics.ignored_detections = ignored;
  metrics.precision = Ratio(metrics.true_positives, metrics.detected_litter);
  metrics.recall = Ratio(metrics.true_positives, metrics.truth_litter);
  const double sum = metrics.precision + metrics.recall;
  metrics.f1 = sum > 0 ? 2 * metrics.precision * metrics.recall / sum : 0.0;
  metrics.class_accuracy = Ratio(class_correct, metrics.true_positives);
  metrics.per_class = CountPerClass(scored, truth, predicted, matched);
  if (visible) metrics.recall_by_masks = CountRecallByMasks(truth, found, *visible, min_pixels);
}

// Confusion and litter/natural accuracy: every detected item against every visible object.
void Confuse(const std::vector<DetectedItem>& detected,
             const std::vector<const TruthObject*>& shown,
             const std::vector<const TruthObject*>& hidden, double radius_m,
             DetectionMetrics& metrics) {
  for (const ClassMetrics& c : metrics.per_class) metrics.confusion_labels.push_back(c.class_name);
  metrics.confusion_labels.push_back("natural");
  metrics.confusion_labels.push_back("none");
  const std::size_t none = metrics.confusion_labels.size() - 1, natural = none - 1;
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < natural; ++i) index[metrics.confusion_labels[i]] = i;
  const auto label = [&](bool litter, const std::string& class_name) {
    const auto it = index.find(class_name);  // not found: a litter item called "natural"
    return litter && it != index.end() ? it->second : natural;
  };
  metrics.confusion.assign(none + 1, std::vector<std::size_t>(none + 1, 0));

  std::vector<const DetectedItem*> items;
  for (const DetectedItem& item : detected) items.push_back(&item);
  const auto matched = Match(items, shown, radius_m);
  std::vector<bool> object_matched(shown.size(), false);
  std::size_t agree = 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (matched[i] == kUnmatched) continue;
    const TruthObject& object = *shown[matched[i]];
    object_matched[matched[i]] = true;
    ++metrics.confusion[label(object.litter, object.class_name)]
                       [label(items[i]->litter, items[i]->class_name)];
    ++metrics.litter_natural_pairs;
    agree += items[i]->litter == object.litter;
  }
  metrics.litter_natural_accuracy = Ratio(agree, metrics.litter_natural_pairs);
  for (const DetectedItem* item : SplitUnmatched(items, matched, hidden, radius_m).first) {
    ++metrics.confusion[none][label(item->litter, item->class_name)];
  }
  for (std::size_t j = 0; j < shown.size(); ++j) {
    if (!object_matched[j])
      ++metrics.confusion[label(shown[j]->litter, shown[j]->class_name)][none];
  }
}

}  // namespace

void DetectionMetricsOptions::Validate() const {
  if (!(match_radius_m > 0) || !std::isfinite(match_radius_m)) {
    throw UsageError("match_radius_m must be > 0, got " + std::to_string(match_radius_m));
  }
  if (!(min_confidence >= 0 && min_confidence <= 1)) {
    throw UsageError("min_confidence must be from 0 to 1, got " + std::to_string(min_confidence));
  }
}

std::size_t DetectionMetrics::Confusion(std::string_view truth_label,
                                        std::string_view predicted_label) const {
  const auto row = std::find(confusion_labels.begin(), confusion_labels.end(), truth_label);
  const auto column = std::find(confusion_labels.begin(), confusion_labels.end(), predicted_label);
  if (row == confusion_labels.end() || column == confusion_labels.end()) return 0;
  return confusion[static_cast<std::size_t>(row - confusion_labels.begin())]
                  [static_cast<std::size_t>(column - confusion_labels.begin())];
}

std::vector<std::pair<std::size_t, std::size_t>> MatchByDistance(
    const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double radius_m) {
  // Candidates found by binary search on b sorted by x, then taken greedily by distance.
  std::vector<std::size_t> b_order(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) b_order[j] = j;
  std::stable_sort(b_order.begin(), b_order.end(),
                   [&](std::size_t p, std::size_t q) { return b[p].x() < b[q].x(); });
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto it = std::lower_bound(b_order.begin(), b_order.end(), a[i].x() - radius_m,
                               [&](std::size_t j, double x) { return b[j].x() < x; });
    for (; it != b_order.end() && b[*it].x() <= a[i].x() + radius_m; ++it) {
      const double distance = (a[i] - b[*it]).norm();
      if (distance <= radius_m) candidates.emplace_back(distance, i, *it);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> a_used(a.size(), false), b_used(b.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> matches;
  for (const auto& [distance, i, j] : candidates) {
    if (a_used[i] || b_used[j]) continue;
    a_used[i] = b_used[j] = true;
    matches.emplace_back(i, j);
  }
  std::sort(matches.begin(), matches.end());
  return matches;
}

DetectionMetrics EvaluateDetections(const std::vector<DetectedItem>& detected,
                                    const std::vector<TruthObject>& truth,
                                    const DetectionMetricsOptions& options,
                                    const std::optional<VisiblePixels>& visible_pixels) {
  options.Validate();
  std::vector<const TruthObject*> shown, hidden;
  for (const TruthObject& object : truth) {
    const bool seen =
        !visible_pixels || MasksSeen(*visible_pixels, object.id, options.min_visible_pixels) > 0;
    (seen ? shown : hidden).push_back(&object);
  }
  DetectionMetrics metrics;
  metrics.hidden_truth = hidden.size();
  metrics.visibility_filtered = visible_pixels.has_value();
  std::vector<DetectedItem> sure;
  for (const DetectedItem& item : detected) {
    if (item.confidence >= options.min_confidence) sure.push_back(item);
  }
  metrics.below_confidence = detected.size() - sure.size();
  ScoreLitter(sure, shown, hidden, options.match_radius_m, visible_pixels,
              options.min_visible_pixels, metrics);
  Confuse(sure, shown, hidden, options.match_radius_m, metrics);
  return metrics;
}

std::vector<TruthObject> ReadTruthObjects(const std::filesystem::path& file, bool litter) {
  std::vector<TruthObject> objects;
  ReadCsv(file, {"id", "class", "x", "y"}, [&](const CsvRow& row) {
    objects.push_back({row.NonEmptyText("id"),
                       row.NonEmptyText("class"),
                       {row.Number("x"), row.Number("y")},
                       litter});
  });
  return objects;
}

std::vector<TruthObject> ReadTruthDirectory(const std::filesystem::path& truth_dir) {
  std::vector<TruthObject> objects = ReadTruthObjects(truth_dir / "litter.csv", true);
  const std::vector<TruthObject> natural = ReadTruthObjects(truth_dir / "natural.csv", false);
  objects.insert(objects.end(), natural.begin(), natural.end());
  return objects;
}

VisiblePixels ReadVisiblePixels(const std::filesystem::path& file) {
  VisiblePixels visible;
  ReadCsv(file, {"object_id", "pixels"}, [&](const CsvRow& row) {
    // Pixels with a depth reading when the file says (an RGB-D detector can place only those).
    const std::size_t pixels = Count(row, row.Has("depth_pixels") ? "depth_pixels" : "pixels");
    visible[row.NonEmptyText("object_id")].push_back(pixels);
  });
  return visible;
}

std::string ToJson(const DetectionMetrics& metrics, const DetectionMetricsOptions& options) {
  nlohmann::ordered_json json;
  json["precision"] = metrics.precision;
  json["recall"] = metrics.recall;
  json["f1"] = metrics.f1;
  json["true_positives"] = metrics.true_positives;
  json["false_positives"] = metrics.false_positives;
  json["false_negatives"] = metrics.false_negatives;
  json["class_accuracy"] = metrics.class_accuracy;
  json["litter_natural_accuracy"] = metrics.litter_natural_accuracy;
  json["litter_natural_pairs"] = metrics.litter_natural_pairs;
  json["truth_litter"] = metrics.truth_litter;
  json["detected_litter"] = metrics.detected_litter;
  json["ignored_detections"] = metrics.ignored_detections;
  json["hidden_truth"] = metrics.hidden_truth;
  json["below_confidence"] = metrics.below_confidence;
  json["per_class"] = nlohmann::ordered_json::object();
  for (const ClassMetrics& c : metrics.per_class) {
    json["per_class"][c.class_name] = {{"truth", c.truth},
                                       {"detected", c.detected},
                                       {"tp", c.true_positives},
                                       {"precision", c.precision},
                                       {"recall", c.recall}};
  }
  if (!metrics.recall_by_masks.empty()) {
    json["recall_by_masks"] = nlohmann::ordered_json::object();
    for (const RecallByMasks& bucket : metrics.recall_by_masks) {
      json["recall_by_masks"][bucket.masks] = {
          {"truth", bucket.truth}, {"tp", bucket.true_positives}, {"recall", bucket.recall}};
    }
  }
  json["confusion"] = nlohmann::ordered_json::object();
  const auto& labels = metrics.confusion_labels;
  for (std::size_t t = 0; t < labels.size(); ++t) {
    nlohmann::ordered_json row = nlohmann::ordered_json::object();
    for (std::size_t p = 0; p < labels.size(); ++p) row[labels[p]] = metrics.confusion[t][p];
    json["confusion"][labels[t]] = row;
  }
  json["match_radius_m"] = options.match_radius_m;
  json["min_confidence"] = options.min_confidence;
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::vector<DetectedItem> TransformItems(std::vector<DetectedItem> items,
                                         const Eigen::Isometry3d& T_reference_estimate) {
  for (DetectedItem& item : items) {
    const Eigen::Vector3d p =
        T_reference_estimate * Eigen::Vector3d(item.position_m.x(), item.position_m.y(), 0);
    item.position_m = p.head<2>();
  }
  return items;
}

}  // namespace littermap::eval

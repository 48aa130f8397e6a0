#pragma once
// Litter detection metrics against the simulator's ground truth (litter.csv, natural.csv and
// masks/visible.csv, sim/ground_truth.hpp and sim/instance_masks.hpp).
// - Matching: one-to-one, greedy: every (detection, truth) pair at most match_radius_m apart
//   (inclusive, in the x-y plane) is a candidate; candidates are taken in order of increasing
//   distance (ties by detection, then truth index), each item and object used once. This is the
//   rule of the TUM associate.py (AssociateByTime) applied to positions. It can pair fewer items
//   than an optimal assignment when clusters overlap, which litter a few decimetres apart rarely
//   does.
// - Litter scores: predicted litter matched to visible truth litter. Matches are true positives,
//   unmatched truth litter false negatives, unmatched predicted litter false positives, except
//   predicted litter that then matches truth litter the visibility filter hid: it may well be
//   right (visible.csv covers only the masked frames), so it is ignored, neither TP nor FP.
// - Ratios over an empty set (precision with no predicted litter, recall with no truth litter,
//   class accuracy with no match, ...) are 1: nothing went wrong; the counts beside them say the
//   set was empty. f1 is 2pr / (p + r), 0 when p + r = 0.
// - Confusion and litter/natural accuracy: ALL detected items matched to ALL visible truth
//   objects (litter and natural) by the same rule. Rows are the truth class (a litter class,
//   "natural" for every natural object, "none" for detections that match nothing), columns the
//   predicted class ("natural" for every item predicted not litter, "none" for truth objects no
//   detection matched). Detections that only match hidden truth objects are left out.
// - Confidence: items less sure than min_confidence are left out before anything is matched, as
//   the report and the heatmap leave them out (their --min-confidence), so a threshold's
//   precision and recall are what the park staff would see.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/object_classes.hpp"

namespace littermap::eval {

struct DetectedItem {
  std::string id;
  std::string class_name;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // run map frame
  double confidence = 1.0;
  bool litter = true;
};

struct TruthObject {
  std::string id;  // the world object id; masks/visible.csv's object_id
  std::string class_name;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  bool litter = true;  // false for natural look-alikes
};

// The pixel counts of each object in the masked frames it appears in, by object id.
using VisiblePixels = std::unordered_map<std::string, std::vector<std::size_t>>;

struct DetectionMetricsOptions {
  double match_radius_m = 0.3;
  std::size_t min_visible_pixels = 100;  // with VisiblePixels: smaller objects are not truth
  double min_confidence = 0.0;           // items less sure are left out (0 to 1)
  void Validate() const;
};

struct ClassMetrics {
  std::string class_name;
  std::size_t truth = 0;           // visible truth litter of the class
  std::size_t detected = 0;        // items predicted litter of the class
  std::size_t true_positives = 0;  // matches whose truth and predicted class are this class
  double precision = 1.0;          // true_positives / detected
  double recall = 1.0;             // true_positives / truth
};

// Recall over the visible truth litter seen in `masks` masked frames (with at least
// min_visible_pixels): an item in one mask was in view for about one mask interval, a glimpse at
// the edge of the image or of the depth range, one in many was passed by.
struct RecallByMasks {
  std::string masks;  // "1", "2", "3+"
  std::size_t truth = 0;
  std::size_t true_positives = 0;
  double recall = 1.0;
};

struct DetectionMetrics {
  std::size_t truth_litter = 0;     // visible truth litter
  std::size_t detected_litter = 0;  // items predicted litter and scored (= TP + FP)
  std::size_t true_positives = 0;
  std::size_t false_positives = 0;
  std::size_t false_negatives = 0;
  std::size_t ignored_detections = 0;  // predicted litter at truth litter the filter hid
  std::size_t hidden_truth = 0;        // truth objects (litter and natural) the filter dropped
  std::size_t below_confidence = 0;    // items (litter and natural) under min_confidence
  bool visibility_filtered = false;    // truth was filtered by visible pixels
  double precision = 1.0;
  double recall = 1.0;
  double f1 = 1.0;
  double class_accuracy = 1.0;           // true positives whose predicted class is the truth class
  double litter_natural_accuracy = 1.0;  // all-items pairs whose litter flags agree
  std::size_t litter_natural_pairs = 0;
  std::vector<ClassMetrics> per_class;         // LitterClasses(), then any other litter class seen
  std::vector<RecallByMasks> recall_by_masks;  // with visible pixels: 1, 2, 3+ masks
  // confusion[t][p]: matches of truth label t to predicted label p (all-items matching).
  std::vector<std::string> confusion_labels;  // per_class's classes, "natural", "none"
  std::vector<std::vector<std::size_t>> confusion;

  // The confusion count of two labels; 0 for a label that is not in confusion_labels.
  std::size_t Confusion(std::string_view truth_label, std::string_view predicted_label) const;
};

// Index pairs (a, b) of a one-to-one greedy matching within radius_m (see above), sorted by a.
std::vector<std::pair<std::size_t, std::size_t>> MatchByDistance(
    const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double radius_m);

// visible_pixels: when given, truth objects with fewer than options.min_visible_pixels in every
// mask (absent objects have none) are not truth. Throws UsageError for invalid options.
DetectionMetrics EvaluateDetections(const std::vector<DetectedItem>& detected,
                                    const std::vector<TruthObject>& truth,
                                    const DetectionMetricsOptions& options,
                                    const std::optional<VisiblePixels>& visible_pixels = {});

// The metrics as a JSON object (2-space indent): the counts and rates above, per_class, the
// confusion table (rows: truth) and the match radius.
std::string ToJson(const DetectionMetrics& metrics, const DetectionMetricsOptions& options);

// Items placed in a run's own map frame, carried into the truth's frame by a rigid transform
// (e.g. TrajectoryMetrics::T_reference_estimate of the run's trajectory onto the reference).
std::vector<DetectedItem> TransformItems(std::vector<DetectedItem> items,
                                         const Eigen::Isometry3d& T_reference_estimate);

// Readers (core/csv_table.hpp). Columns are found by header name, in any order; extra columns
// are ignored. Errors throw BadInputError naming FILE:LINE and the column (LINE 1: the header).
// litter.csv or natural.csv (id, class, x, y required); `litter` says which the file holds.
std::vector<TruthObject> ReadTruthObjects(const std::filesystem::path& file, bool litter);
// A simulator TRUTH_DIR's litter.csv and natural.csv together.
std::vector<TruthObject> ReadTruthDirectory(const std::filesystem::path& truth_dir);
// masks/visible.csv (object_id, pixels required): the pixel counts of each object, of its pixels
// with a depth reading when the file has a depth_pixels column.
VisiblePixels ReadVisiblePixels(const std::filesystem::path& file);

}  // namespace littermap::eval

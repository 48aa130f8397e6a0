// Detection metrics against small scenes with known answers: matching radius and one-to-one
// matching, class confusion, natural look-alikes taken for litter, the visibility filter, the
// confidence threshold, and the CSV readers' error messages. Counts are exact; ratios are exact
// fractions, compared with a 1e-12 tolerance (a few floating-point divisions).

#include "eval/detection_metrics.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::eval {
namespace {

using test::ExpectBadInput;

constexpr double kTolerance = 1e-12;

DetectedItem Item(const std::string& class_name, double x, double y, bool litter = true) {
  static int next_id = 0;
  return {"d" + std::to_string(next_id++), class_name, {x, y}, 1.0, litter};
}

TruthObject Litter(const std::string& id, const std::string& class_name, double x, double y) {
  return {id, class_name, {x, y}, true};
}

TruthObject Natural(const std::string& id, const std::string& class_name, double x, double y) {
  return {id, class_name, {x, y}, false};
}

const ClassMetrics& ClassRow(const DetectionMetrics& metrics, const std::string& name) {
  for (const ClassMetrics& c : metrics.per_class) {
    if (c.class_name == name) return c;
  }
  throw std::runtime_error("no per-class row " + name);
}

void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(DetectionMetrics, PerfectDetectionScoresOne) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0), Litter("2", "bottle", 4, 1),
                                          Litter("3", "plastic_bag", -2, 7)};
  const std::vector<DetectedItem> detected = {Item("plastic_bag", -2, 7), Item("can", 0, 0),
                                              Item("bottle", 4, 1)};
  const DetectionMetrics metrics = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(metrics.true_positives, 3u);
  EXPECT_EQ(metrics.false_positives, 0u);
  EXPECT_EQ(metrics.false_negatives, 0u);
  EXPECT_EQ(metrics.truth_litter, 3u);
  EXPECT_EQ(metrics.detected_litter, 3u);
  EXPECT_NEAR(metrics.precision, 1.0, kTolerance);
  EXPECT_NEAR(metrics.recall, 1.0, kTolerance);
  EXPECT_NEAR(metrics.f1, 1.0, kTolerance);
  EXPECT_NEAR(metrics.class_accuracy, 1.0, kTolerance);
  EXPECT_EQ(metrics.litter_natural_pairs, 3u);
  EXPECT_NEAR(metrics.litter_natural_accuracy, 1.0, kTolerance);
  ASSERT_EQ(metrics.per_class.size(), LitterClasses().size());
  EXPECT_EQ(ClassRow(metrics, "can").truth, 1u);
  EXPECT_EQ(ClassRow(metrics, "can").detected, 1u);
  EXPECT_EQ(ClassRow(metrics, "can").true_positives, 1u);
  EXPECT_EQ(ClassRow(metrics, "cup").truth, 0u);
  EXPECT_EQ(metrics.Confusion("bottle", "bottle"), 1u);
  EXPECT_EQ(metrics.Confusion("none", "can"), 0u);
}

TEST(DetectionMetrics, OffsetJustInsideTheRadiusMatchesJustOutsideDoesNot) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 10, 10)};
  // 0.29 m and 0.31 m from the truth along a diagonal, radius 0.3 m.
  const double inside = 0.29 / std::sqrt(2.0), outside = 0.31 / std::sqrt(2.0);
  const DetectionMetrics matched =
      EvaluateDetections({Item("can", 10 + inside, 10 + inside)}, truth, {});
  EXPECT_EQ(matched.true_positives, 1u);
  EXPECT_EQ(matched.false_positives, 0u);
  EXPECT_EQ(matched.false_negatives, 0u);
  const DetectionMetrics missed =
      EvaluateDetections({Item("can", 10 + outside, 10 - outside)}, truth, {});
  EXPECT_EQ(missed.true_positives, 0u);
  EXPECT_EQ(missed.false_positives, 1u);
  EXPECT_EQ(missed.false_negatives, 1u);
  EXPECT_NEAR(missed.f1, 0.0, kTolerance);
  EXPECT_EQ(missed.Confusion("none", "can"), 1u);
  EXPECT_EQ(missed.Confusion("can", "none"), 1u);
  // A wider radius takes it in.
  DetectionMetricsOptions options;
  options.match_radius_m = 0.5;
  EXPECT_EQ(
      EvaluateDetections({Item("can", 10 + outside, 10 - outside)}, truth, options).true_positives,
      1u);
}

TEST(DetectionMetrics, MatchingIsOneToOne) {
  // Two detections of one can: the nearer one is the true positive, the other a false positive.
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0)};
  const std::vector<DetectedItem> detected = {Item("cup", 0.1, 0), Item("can", 0, 0.05)};
  const DetectionMetrics metrics = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(metrics.true_positives, 1u);
  EXPECT_EQ(metrics.false_positives, 1u);
  EXPECT_EQ(metrics.false_negatives, 0u);
  EXPECT_NEAR(metrics.precision, 0.5, kTolerance);
  EXPECT_NEAR(metrics.recall, 1.0, kTolerance);
  EXPECT_NEAR(metrics.f1, 2.0 / 3.0, kTolerance);
  EXPECT_NEAR(metrics.class_accuracy, 1.0, kTolerance);  // the nearer one says "can"
  EXPECT_EQ(metrics.Confusion("can", "can"), 1u);
  EXPECT_EQ(metrics.Confusion("none", "cup"), 1u);
}

TEST(DetectionMetrics, MatchingTakesNearestPairsFirst) {
  // Greedy by distance, as documented: a1-b0 (0.05 m) is taken first, which leaves a0 (0.2 m
  // from b0) and b1 (0.2 m from a1) unmatched, where an optimal assignment would pair both.
  const std::vector<Eigen::Vector2d> a = {{0, 0}, {0.25, 0}};
  const std::vector<Eigen::Vector2d> b = {{0.2, 0}, {0.45, 0}};
  const auto matches = MatchByDistance(a, b, 0.21);
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(matches[0], (std::pair<std::size_t, std::size_t>(1, 0)));
  // Exactly at the radius still matches (inclusive); 1e-9 m further does not.
  EXPECT_EQ(MatchByDistance({{0, 0}}, {{0, 0.5}}, 0.5).size(), 1u);
  EXPECT_EQ(MatchByDistance({{0, 0}}, {{0, 0.5 + 1e-9}}, 0.5).size(), 0u);
}

TEST(DetectionMetrics, WrongClassIsAMatchButNotClassCorrect) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0), Litter("2", "bottle", 5, 0)};
  const std::vector<DetectedItem> detected = {Item("bottle", 0, 0), Item("bottle", 5, 0)};
  const DetectionMetrics metrics = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(metrics.true_positives, 2u);
  EXPECT_NEAR(metrics.precision, 1.0, kTolerance);
  EXPECT_NEAR(metrics.class_accuracy, 0.5, kTolerance);
  const ClassMetrics& can = ClassRow(metrics, "can");
  EXPECT_EQ(can.truth, 1u);
  EXPECT_EQ(can.detected, 0u);
  EXPECT_EQ(can.true_positives, 0u);
  EXPECT_NEAR(can.precision, 1.0, kTolerance);  // nothing predicted "can": no false claim
  EXPECT_NEAR(can.recall, 0.0, kTolerance);
  const ClassMetrics& bottle = ClassRow(metrics, "bottle");
  EXPECT_EQ(bottle.truth, 1u);
  EXPECT_EQ(bottle.detected, 2u);
  EXPECT_EQ(bottle.true_positives, 1u);
  EXPECT_NEAR(bottle.precision, 0.5, kTolerance);
  EXPECT_NEAR(bottle.recall, 1.0, kTolerance);
  EXPECT_EQ(metrics.Confusion("can", "bottle"), 1u);
  EXPECT_EQ(metrics.Confusion("bottle", "bottle"), 1u);
  EXPECT_EQ(metrics.Confusion("can", "can"), 0u);
}

TEST(DetectionMetrics, NaturalTakenForLitterIsAFalsePositive) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0), Natural("2", "leaf", 3, 0),
                                          Natural("3", "stone", 6, 0),
                                          Natural("4", "mushroom", 9, 0)};
  const std::vector<DetectedItem> detected = {
      Item("can", 0, 0), Item("cup", 3, 0),  // the leaf taken for a cup
      Item("stone", 6, 0, false), Item("natural", 9, 0, false)};
  const DetectionMetrics metrics = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(metrics.truth_litter, 1u);
  EXPECT_EQ(metrics.detected_litter, 2u);
  EXPECT_EQ(metrics.true_positives, 1u);
  EXPECT_EQ(metrics.false_positives, 1u);
  EXPECT_NEAR(metrics.precision, 0.5, kTolerance);
  EXPECT_NEAR(metrics.recall, 1.0, kTolerance);
  EXPECT_EQ(metrics.litter_natural_pairs, 4u);
  EXPECT_NEAR(metrics.litter_natural_accuracy, 0.75, kTolerance);
  EXPECT_EQ(metrics.Confusion("natural", "cup"), 1u);
  EXPECT_EQ(metrics.Confusion("natural", "natural"), 2u);
  EXPECT_EQ(metrics.Confusion("can", "can"), 1u);
  EXPECT_EQ(metrics.Confusion("none", "cup"), 0u);
}

TEST(DetectionMetrics, ItemsLessSureThanTheThresholdAreLeftOut) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0), Litter("2", "cup", 3, 0),
                                          Natural("3", "mushroom", 6, 0)};
  std::vector<DetectedItem> detected = {Item("can", 0, 0), Item("cup", 3, 0),
                                        Item("cup", 6, 0),  // the mushroom taken for a cup
                                        Item("natural", 3.1, 0, false)};
  detected[0].confidence = 0.9;
  detected[1].confidence = 0.3;  // just at the threshold: kept
  detected[2].confidence = 0.2;
  detected[3].confidence = 0.1;
  const DetectionMetrics all = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(all.false_positives, 1u);
  EXPECT_EQ(all.below_confidence, 0u);
  DetectionMetricsOptions options;
  options.min_confidence = 0.3;
  const DetectionMetrics sure = EvaluateDetections(detected, truth, options);
  EXPECT_EQ(sure.below_confidence, 2u);
  EXPECT_EQ(sure.detected_litter, 2u);
  EXPECT_EQ(sure.true_positives, 2u);
  EXPECT_EQ(sure.false_positives, 0u);
  EXPECT_NEAR(sure.precision, 1.0, kTolerance);
  // The natural item left out no longer pairs with anything; the mushroom is unmatched.
  EXPECT_EQ(sure.Confusion("natural", "none"), 1u);
  EXPECT_EQ(sure.Confusion("natural", "cup"), 0u);
  options.min_confidence = 0.95;
  const DetectionMetrics none = EvaluateDetections(detected, truth, options);
  EXPECT_EQ(none.detected_litter, 0u);
  EXPECT_NEAR(none.recall, 0.0, kTolerance);
}

TEST(DetectionMetrics, VisibilityFilterDropsObjectsTheCameraBarelySaw) {
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0), Litter("2", "can", 5, 0),
                                          Litter("3", "cup", 10, 0), Natural("4", "leaf", 15, 0)};
  const VisiblePixels visible = {{"1", {500}}, {"2", {20}}, {"4", {10}}};  // 3 never in a mask
  const std::vector<DetectedItem> detected = {Item("can", 0, 0), Item("can", 5, 0),
                                              Item("cup", 15, 0)};  // the hidden leaf as litter
  const DetectionMetrics unfiltered = EvaluateDetections(detected, truth, {});
  EXPECT_EQ(unfiltered.truth_litter, 3u);
  EXPECT_EQ(unfiltered.true_positives, 2u);
  EXPECT_EQ(unfiltered.false_negatives, 1u);
  EXPECT_EQ(unfiltered.false_positives, 1u);
  EXPECT_EQ(unfiltered.hidden_truth, 0u);

  // min 100 pixels: only 1 is truth. The detection at 2 may be right (a frame without a mask
  // could show it well): ignored. The one at the hidden leaf is not litter anyway: FP.
  const DetectionMetrics filtered = EvaluateDetections(detected, truth, {}, visible);
  EXPECT_EQ(filtered.hidden_truth, 3u);
  EXPECT_EQ(filtered.truth_litter, 1u);
  EXPECT_EQ(filtered.true_positives, 1u);
  EXPECT_EQ(filtered.false_negatives, 0u);
  EXPECT_EQ(filtered.false_positives, 1u);
  EXPECT_EQ(filtered.ignored_detections, 1u);
  EXPECT_EQ(filtered.detected_litter, 2u);
  EXPECT_NEAR(filtered.recall, 1.0, kTolerance);
  EXPECT_NEAR(filtered.precision, 0.5, kTolerance);
  EXPECT_EQ(filtered.litter_natural_pairs, 1u);  // only object 1 is visible truth
  EXPECT_EQ(filtered.Confusion("none", "can"), 0u);
  EXPECT_EQ(filtered.Confusion("none", "cup"), 0u);

  // The threshold is inclusive: 20 pixels are enough at min 20.
  DetectionMetricsOptions options;
  options.min_visible_pixels = 20;
  const DetectionMetrics at_twenty = EvaluateDetections(detected, truth, options, visible);
  EXPECT_EQ(at_twenty.truth_litter, 2u);
  EXPECT_EQ(at_twenty.true_positives, 2u);
  EXPECT_EQ(at_twenty.ignored_detections, 0u);
}

TEST(DetectionMetrics, RecallIsSplitByTheMasksAnItemWasSeenIn) {
  // Six visible litter items: two glimpsed in one mask, one seen in two, three in more.
  const std::vector<TruthObject> truth = {Litter("1", "can", 0, 0),  Litter("2", "can", 5, 0),
                                          Litter("3", "cup", 10, 0), Litter("4", "cup", 15, 0),
                                          Litter("5", "can", 20, 0), Litter("6", "can", 25, 0)};
  const VisiblePixels visible = {{"1", {150, 40}},       {"2", {30, 120}},
                                 {"3", {100, 400, 90}},  {"4", {900, 800, 700}},
                                 {"5", {150, 300, 400}}, {"6", {120, 130, 140, 150}}};
  // Found: one glimpse, the two-mask item, two of three seen often.
  const std::vector<DetectedItem> detected = {Item("can", 0, 0), Item("cup", 10, 0),
                                              Item("cup", 15, 0), Item("can", 20, 0)};
  const DetectionMetrics metrics = EvaluateDetections(detected, truth, {}, visible);
  ASSERT_EQ(metrics.recall_by_masks.size(), 3u);
  const auto expect = [&](std::size_t k, const char* masks, std::size_t truth_count,
                          std::size_t found) {
    EXPECT_EQ(metrics.recall_by_masks[k].masks, masks);
    EXPECT_EQ(metrics.recall_by_masks[k].truth, truth_count) << masks;
    EXPECT_EQ(metrics.recall_by_masks[k].true_positives, found) << masks;
    EXPECT_NEAR(metrics.recall_by_masks[k].recall, double(found) / double(truth_count), kTolerance)
        << masks;
  };
  expect(0, "1", 2, 1);
  expect(1, "2", 1, 1);
  expect(2, "3+", 3, 2);
  // Masks under the threshold do not count: at 200 pixels items 1, 2 and 6 are hidden, item 3
  // was seen in one mask and item 5 in two.
  DetectionMetricsOptions options;
  options.min_visible_pixels = 200;
  const DetectionMetrics strict = EvaluateDetections(detected, truth, options, visible);
  EXPECT_EQ(strict.truth_litter, 3u);
  for (const RecallByMasks& bucket : strict.recall_by_masks) {
    EXPECT_EQ(bucket.truth, 1u) << bucket.masks;
    EXPECT_EQ(bucket.true_positives, 1u) << bucket.masks;
  }
  // Without visibility there is no split.
  EXPECT_TRUE(EvaluateDetections(detected, truth, {}).recall_by_masks.empty());
}

TEST(DetectionMetrics, EmptySetsGiveVacuousRatios) {
  const DetectionMetrics nothing = EvaluateDetections({}, {}, {});
  EXPECT_NEAR(nothing.precision, 1.0, kTolerance);
  EXPECT_NEAR(nothing.recall, 1.0, kTolerance);
  EXPECT_NEAR(nothing.f1, 1.0, kTolerance);
  EXPECT_NEAR(nothing.class_accuracy, 1.0, kTolerance);
  const DetectionMetrics blind = EvaluateDetections({}, {Litter("1", "can", 0, 0)}, {});
  EXPECT_NEAR(blind.precision, 1.0, kTolerance);
  EXPECT_NEAR(blind.recall, 0.0, kTolerance);
  EXPECT_NEAR(blind.f1, 0.0, kTolerance);
  EXPECT_EQ(blind.false_negatives, 1u);
}

TEST(DetectionMetrics, UnknownLitterClassGetsItsOwnRow) {
  const DetectionMetrics metrics =
      EvaluateDetections({Item("tyre", 0, 0)}, {Litter("1", "can", 0, 0)}, {});
  EXPECT_EQ(metrics.per_class.back().class_name, "tyre");
  EXPECT_EQ(metrics.per_class.back().detected, 1u);
  EXPECT_EQ(metrics.Confusion("can", "tyre"), 1u);
}

TEST(DetectionMetrics, InvalidRadiusIsAUsageError) {
  DetectionMetricsOptions options;
  options.match_radius_m = 0;
  EXPECT_THROW(EvaluateDetections({}, {}, options), UsageError);
  options = {};
  options.min_confidence = 1.5;
  EXPECT_THROW(EvaluateDetections({}, {}, options), UsageError);
}

TEST(DetectionMetricsFiles, ReadersFindColumnsByName) {
  test::TempDir dir;
  WriteFile(dir / "litter.csv", "id,class,x,y,z,size_m\r\n7,can,1.0,2.0,0.05,0.12\r\n");
  const auto truth = ReadTruthObjects(dir / "litter.csv", true);
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_EQ(truth[0].id, "7");
  EXPECT_EQ(truth[0].class_name, "can");
  EXPECT_TRUE(truth[0].litter);
  EXPECT_FALSE(ReadTruthObjects(dir / "litter.csv", false)[0].litter);

  WriteFile(dir / "visible.csv", "frame,object_id,pixels\n0,7,40\n1,7,300\n2,7,12\n2,9,5\n");
  const VisiblePixels visible = ReadVisiblePixels(dir / "visible.csv");
  EXPECT_EQ(visible.at("7"), (std::vector<std::size_t>{40, 300, 12}));
  EXPECT_EQ(visible.at("9"), (std::vector<std::size_t>{5}));
}

TEST(DetectionMetricsFiles, ErrorsNameFileLineAndColumn) {
  test::TempDir dir;
  const std::string visible = (dir / "visible.csv").string();
  WriteFile(visible, "frame,object_id,pixels\n0,3,-4\n");
  ExpectBadInput([&] { ReadVisiblePixels(visible); }, visible + ":2: column 'pixels'");
  const std::string missing = (dir / "missing.csv").string();
  ExpectBadInput([&] { ReadTruthObjects(missing, true); }, missing);
}

}  // namespace
}  // namespace littermap::eval

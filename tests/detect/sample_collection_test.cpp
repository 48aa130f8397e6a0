// The labels `samples` gives objects from the simulator's truth, and its summary line.

#include "detect/sample_collection.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace littermap::detect {
namespace {

const std::vector<eval::TruthObject> kTruth = {{"1", "can", {0, 0}, true},
                                               {"2", "stone", {1, 0}, false}};

TEST(LabelAt, TheNearestTruthObjectWithinTheRadiusGivesItsClass) {
  EXPECT_EQ(LabelAt(kTruth, {0.1, 0}, 0.2), "can");
  EXPECT_EQ(LabelAt(kTruth, {0.2, 0}, 0.2), "can");  // inclusive
  EXPECT_EQ(LabelAt(kTruth, {0.95, 0.1}, 0.2), "natural");
  EXPECT_EQ(LabelAt(kTruth, {0.45, 0}, 0.5), "can");  // both within: the nearer
}

TEST(LabelAt, ClutterFarFromTruthAmbiguousInBetween) {
  EXPECT_EQ(LabelAt(kTruth, {0, 0.3}, 0.2), "");  // between the radius and twice it
  EXPECT_EQ(LabelAt(kTruth, {0, 0.4}, 0.2), "");  // twice the radius, inclusive
  EXPECT_EQ(LabelAt(kTruth, {0, 0.41}, 0.2), "clutter");
  EXPECT_EQ(LabelAt({}, {0, 0}, 0.2), "clutter");
}

TEST(SampleCollection, SummaryCountsEachLabel) {
  SampleCollection collection;
  collection.samples = 5;
  collection.label_counts = {{"can", 2}, {"clutter", 3}};
  EXPECT_EQ(CollectionSummary(collection, "out/samples"),
            "wrote out/samples: 5 samples (can 2, clutter 3)");
  EXPECT_EQ(CollectionSummary({}, "s"), "wrote s: 0 samples ()");
}

}  // namespace
}  // namespace littermap::detect

#include "detect/item_fusion.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

Sighting At(double x, double y, std::vector<double> p, TimestampNs t = 0, double range = 2.0) {
  Sighting s;
  s.position_world_m = {x, y, 0};
  s.class_probabilities = std::move(p);
  s.stamp_ns = t;
  s.range_m = range;
  s.size_m = 0.1;
  return s;
}

TEST(ItemFusion, SightingsOfTwoObjectsBecomeTwoItemsWithMeanPositionAndClasses) {
  ItemFusion fusion({0.25, 3}, 2);
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.03);  // 3 cm sighting scatter
  for (int i = 0; i < 20; ++i) {
    fusion.Add(At(1 + noise(random), 2 + noise(random), {0.8, 0.2}, 100 + i));
    fusion.Add(At(4 + noise(random), 2 + noise(random), {0.3, 0.7}, 100 + i));
  }
  const auto items = fusion.Fuse().items;
  ASSERT_EQ(items.size(), 2u);
  EXPECT_NEAR(items[0].position_world_m.x(), 1.0, 0.03);  // mean of 20: sigma 7 mm
  EXPECT_NEAR(items[1].position_world_m.x(), 4.0, 0.03);
  EXPECT_EQ(items[0].best_class, 0u);
  EXPECT_EQ(items[1].best_class, 1u);
  EXPECT_NEAR(items[1].confidence, 0.7, 1e-9);
  EXPECT_EQ(items[0].views, 20);
  EXPECT_EQ(items[0].first_seen_ns, 100);
  EXPECT_EQ(items[0].last_seen_ns, 119);
}

TEST(ItemFusion, ItemsSeenInTooFewViewsAreDropped) {
  ItemFusion fusion({0.25, 3}, 1);
  fusion.Add(At(0, 0, {1.0}));
  fusion.Add(At(0.05, 0, {1.0}));
  fusion.Add(At(5, 5, {1.0}));
  EXPECT_TRUE(fusion.Fuse().items.empty());
  fusion.Add(At(0.02, 0.01, {1.0}));
  ASSERT_EQ(fusion.Fuse().items.size(), 1u);
  EXPECT_EQ(fusion.candidates(), 2u);
}

// detections.csv names each sighting's item by the id Add returns, so an item must keep that id in
// items.csv when candidates seen before it were dropped.
TEST(ItemFusion, AnItemKeepsTheIdItsSightingsWereGiven) {
  ItemFusion fusion({0.25, 3}, 1);
  EXPECT_EQ(fusion.Add(At(5, 5, {1.0})), 1);  // seen once: dropped
  int id = 0;
  for (int i = 0; i < 3; ++i) id = fusion.Add(At(0.01 * i, 0, {1.0}));
  EXPECT_EQ(id, 2);
  const std::vector<LitterItem> items = fusion.Fuse().items;
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].id, 2);
}

TEST(ItemFusion, NearSightingsCountMoreThanFarOnes) {
  ItemFusion fusion({0.5, 1}, 1);
  fusion.Add(At(0.0, 0, {1.0}, 0, 1.0));  // weight 1
  fusion.Add(At(0.3, 0, {1.0}, 0, 3.0));  // weight 1/9
  const auto items = fusion.Fuse().items;
  ASSERT_EQ(items.size(), 1u);
  EXPECT_NEAR(items[0].position_world_m.x(), 0.3 / 10.0, 1e-9);
}

TEST(ItemFusion, FramesThatCouldSeeAnItemAndDidNotAreMissedViews) {
  ItemFusion fusion({0.25, 1, 0.0}, 1);
  const auto in_view = [](const Eigen::Vector3d& place, double) { return place.x() < 2; };
  for (std::size_t frame = 0; frame < 10; ++frame) {
    if (frame < 4) {  // seen in frames 0-3 at x 1 and in frame 0 only at x 3 (out of view)
      Sighting near = At(1, 0, {1.0});
      near.frame = frame;
      fusion.Add(near);
      if (frame == 0) fusion.Add(At(3, 0, {1.0}));
    }
    fusion.Observe(frame, in_view);
  }
  const auto items = fusion.Fuse().items;
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].views, 4);
  EXPECT_EQ(items[0].missed_views, 6);  // frames 4-9: in view, not seen
  EXPECT_NEAR(items[0].seen_share(), 0.4, 1e-12);
  EXPECT_EQ(items[1].missed_views, 0);  // never in view again
  EXPECT_EQ(items[1].seen_share(), 1.0);
}

// One item seen in frames 0, 2 and 4 of five frames that could all see it (share 0.6).
ItemFusion SeenInThreeOfFiveFrames(double min_seen_share) {
  ItemFusion fusion({0.25, 1, min_seen_share}, 1);
  for (std::size_t frame = 0; frame < 5; ++frame) {
    if (frame % 2 == 0) {
      Sighting s = At(1, 0, {1.0});
      s.frame = frame;
      fusion.Add(s);
    }
    fusion.Observe(frame, [](const Eigen::Vector3d&, double) { return true; });
  }
  return fusion;
}

TEST(ItemFusion, ItemsSeenInTooSmallAShareOfTheirChancesAreDropped) {
  for (const double kept : {0.5, 0.6}) {
    EXPECT_EQ(SeenInThreeOfFiveFrames(kept).Fuse().items.size(), 1u) << kept;
    EXPECT_EQ(SeenInThreeOfFiveFrames(kept).Fuse().seldom_seen, 0u) << kept;
  }
  EXPECT_TRUE(SeenInThreeOfFiveFrames(0.61).Fuse().items.empty());
  EXPECT_EQ(SeenInThreeOfFiveFrames(0.61).Fuse().seldom_seen, 1u);
  EXPECT_THROW(ItemFusion({0.25, 1, 1.5}, 1), UsageError);
}

// A bottle seen twelve times at the far edge of the range, a dozen pixels that the classifier
// thinks natural, then four times close by as a bottle: its class is what the close views say.
TEST(ItemFusion, TheClassComesFromTheLargestViews) {
  const auto fuse = [](int class_views) {
    FusionOptions options;
    options.class_views = class_views;
    ItemFusion fusion(options, 2);
    for (int i = 0; i < 16; ++i) {
      const bool close = i >= 12;
      Sighting s = At(1, 0, close ? std::vector<double>{0.9, 0.1} : std::vector<double>{0.3, 0.7});
      s.pixels = close ? 400 + i : 12;
      fusion.Add(s);
    }
    return fusion.Fuse().items;
  };
  const std::vector<LitterItem> largest = fuse(4);
  ASSERT_EQ(largest.size(), 1u);
  EXPECT_NEAR(largest[0].class_probabilities[0], 0.9, 1e-9);
  EXPECT_EQ(largest[0].views, 16);
  const std::vector<LitterItem> six = fuse(6);  // the four close views and two far ones
  EXPECT_NEAR(six[0].class_probabilities[0], (4 * 0.9 + 2 * 0.3) / 6, 1e-9);
  const std::vector<LitterItem> all = fuse(0);
  EXPECT_NEAR(all[0].class_probabilities[0], (4 * 0.9 + 12 * 0.3) / 16, 1e-9);
}

// A bag seen in fragments that scatter over 0.3 m: the second fragment falls just outside the
// radius of the first and starts a candidate of its own; later fragments land between the two.
// Whatever the order, one item comes out, with every view and the largest views' classes.
TEST(ItemFusion, CandidatesWithinTheRadiusOfEachOtherBecomeOneItem) {
  ItemFusion fusion({0.25, 3}, 2);
  const double xs[] = {0.0, 0.26, 0.1, 0.2, 0.05, 0.24, 0.12, 0.15};
  std::vector<int> candidates;
  for (std::size_t i = 0; i < std::size(xs); ++i) {
    Sighting s =
        At(xs[i], 0, i == 1 ? std::vector<double>{0.9, 0.1} : std::vector<double>{0.8, 0.2});
    s.frame = i;
    s.pixels = i == 1 ? 500 : 100;
    candidates.push_back(fusion.Add(s));
  }
  ASSERT_EQ(fusion.candidates(), 2u);  // the greedy association made two
  const FusedItems fused = fusion.Fuse();
  ASSERT_EQ(fused.items.size(), 1u);
  EXPECT_EQ(fused.merged, 1u);
  EXPECT_EQ(fused.items[0].id, 1);
  EXPECT_EQ(fused.items[0].views, 8);
  EXPECT_NEAR(fused.items[0].class_probabilities[0], (0.9 + 7 * 0.8) / 8, 1e-9);
  EXPECT_NEAR(fused.items[0].position_world_m.x(),
              (0.0 + 0.26 + 0.1 + 0.2 + 0.05 + 0.24 + 0.12 + 0.15) / 8, 1e-9);
  for (const int candidate : candidates) {
    EXPECT_EQ(fused.item_of_candidate.at(static_cast<std::size_t>(candidate) - 1), 1);
  }
}

// A cup 0.21 m from a plastic bag, kept apart by the order of their sightings, stays apart: their
// likeliest classes differ. The same sightings of one kind become one item.
TEST(ItemFusion, NeighboursOfDifferentClassesStayApart) {
  const auto fuse = [](const std::vector<double>& second) {
    ItemFusion fusion({0.25, 1}, 2);
    const std::vector<double> first = {0.9, 0.1};
    fusion.Add(At(0.0, 0, first));
    fusion.Add(At(0.26, 0, second));
    fusion.Add(At(0.05, 0, first));
    fusion.Add(At(0.21, 0, second));  // the candidates' means now 0.21 m apart
    return fusion.Fuse();
  };
  const FusedItems apart = fuse({0.2, 0.8});
  ASSERT_EQ(apart.items.size(), 2u);
  EXPECT_EQ(apart.merged, 0u);
  EXPECT_EQ(apart.items[0].best_class, 0u);
  EXPECT_EQ(apart.items[1].best_class, 1u);
  EXPECT_EQ(fuse({0.8, 0.2}).items.size(), 1u);
}

// Two cans 0.4 m apart stay two items, and a frame that saw one of two merged candidates saw the
// merged item: its missed views are the frames that saw neither.
TEST(ItemFusion, MergingKeepsDistinctItemsAndCountsMissedViewsOfTheWhole) {
  ItemFusion fusion({0.25, 1, 0.0}, 1);
  const auto everywhere = [](const Eigen::Vector3d&, double) { return true; };
  for (std::size_t frame = 0; frame < 6; ++frame) {
    // Frames 0-2 see a fragment at x 0, frame 3 one at x 0.26 (a candidate of its own), frame 4
    // one at x 0.12 (joins the first); frame 5 sees neither. A can at x 3 is seen in every frame,
    // another at x 3.4 in frame 0.
    const double fragment_x[] = {0.0, 0.0, 0.0, 0.26, 0.12};
    Sighting fragment = At(fragment_x[std::min<std::size_t>(frame, 4)], 0, {1.0});
    fragment.frame = frame;
    if (frame < 5) fusion.Add(fragment);
    Sighting can = At(3, 0, {1.0});
    can.frame = frame;
    fusion.Add(can);
    if (frame == 0) {
      Sighting other = At(3.4, 0, {1.0});
      other.frame = frame;
      fusion.Add(other);
    }
    fusion.Observe(frame, everywhere);
  }
  const FusedItems fused = fusion.Fuse();
  ASSERT_EQ(fused.items.size(), 3u);
  EXPECT_EQ(fused.merged, 1u);
  EXPECT_EQ(fused.items[0].views, 5);
  EXPECT_EQ(fused.items[0].missed_views, 1);  // frame 5 only
  EXPECT_NEAR(fused.items[1].position_world_m.x(), 3.0, 1e-9);
  EXPECT_NEAR(fused.items[2].position_world_m.x(), 3.4, 1e-9);
}

TEST(ItemFusion, RejectsBadOptionsAndProbabilityCounts) {
  EXPECT_THROW(ItemFusion({0.0, 3}, 2), UsageError);
  EXPECT_THROW(ItemFusion({0.2, 0}, 2), UsageError);
  FusionOptions views;
  views.class_views = -1;
  EXPECT_THROW(ItemFusion(views, 2), UsageError);
  for (const double p : {0.0, 1.5}) {
    FusionOptions litter;
    litter.min_litter_probability = p;
    EXPECT_THROW(ItemFusion(litter, 2), UsageError) << p;
  }
  ItemFusion fusion({0.25, 1}, 2);
  EXPECT_THROW(fusion.Add(At(0, 0, {1.0})), InternalError);
}

}  // namespace
}  // namespace littermap::detect

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
  const auto items = fusion.Items();
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
  EXPECT_TRUE(fusion.Items().empty());
  fusion.Add(At(0.02, 0.01, {1.0}));
  ASSERT_EQ(fusion.Items().size(), 1u);
  EXPECT_EQ(fusion.candidates(), 2u);
}

TEST(ItemFusion, NearSightingsCountMoreThanFarOnes) {
  ItemFusion fusion({0.5, 1}, 1);
  fusion.Add(At(0.0, 0, {1.0}, 0, 1.0));  // weight 1
  fusion.Add(At(0.3, 0, {1.0}, 0, 3.0));  // weight 1/9
  const auto items = fusion.Items();
  ASSERT_EQ(items.size(), 1u);
  EXPECT_NEAR(items[0].position_world_m.x(), 0.3 / 10.0, 1e-9);
}

TEST(ItemFusion, RejectsBadOptionsAndProbabilityCounts) {
  EXPECT_THROW(ItemFusion({0.0, 3}, 2), UsageError);
  EXPECT_THROW(ItemFusion({0.2, 0}, 2), UsageError);
  ItemFusion fusion({0.25, 1}, 2);
  EXPECT_THROW(fusion.Add(At(0, 0, {1.0})), InternalError);
}

}  // namespace
}  // namespace littermap::detect

#include "reconstruct/landmark_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace littermap::reconstruct {
namespace {

struct Trunk {
  Eigen::Vector2d centre;
  double radius_m;
};

// A constellation of seven trunks of different radii around `at`, as in a park.
std::vector<Trunk> Constellation(const Eigen::Vector2d& at) {
  return {{at + Eigen::Vector2d(3, 4), 0.2},   {at + Eigen::Vector2d(-2, 6), 0.35},
          {at + Eigen::Vector2d(7, -3), 0.15}, {at + Eigen::Vector2d(-5, -4), 0.3},
          {at + Eigen::Vector2d(10, 5), 0.25}, {at + Eigen::Vector2d(1, -7), 0.4},
          {at + Eigen::Vector2d(-8, 2), 0.12}};
}

// The trunks within 20 m of the true pose, seen from the pose the robot believes it is at:
// centres in the base frame from the true pose, with 2 cm noise.
std::vector<LandmarkObservation> Observe(const std::vector<Trunk>& trunks,
                                         const PlanarPose& T_world_true, std::mt19937* rng) {
  std::normal_distribution<double> noise(0, 0.02);
  std::vector<LandmarkObservation> seen;
  const PlanarPose T_true_world = Inverse(T_world_true);
  for (const Trunk& t : trunks) {
    const double c = std::cos(T_true_world.theta_rad), s = std::sin(T_true_world.theta_rad);
    const Eigen::Vector2d p(T_true_world.x_m + c * t.centre.x() - s * t.centre.y(),
                            T_true_world.y_m + s * t.centre.x() + c * t.centre.y());
    if (p.norm() > 20) continue;
    LandmarkObservation o;
    o.centre_base = p + Eigen::Vector2d(noise(*rng), noise(*rng));
    o.radius_m = t.radius_m + noise(*rng) * 0.5;
    o.covariance_base = 0.02 * 0.02 * Eigen::Matrix2d::Identity();
    seen.push_back(o);
  }
  return seen;
}

class LandmarkMapTest : public ::testing::Test {
 protected:
  // Drives along y = 0 from x0 to x1 (key frames every metre), seeing the trunks; the robot
  // believes it is offset by `drift` from the truth. Returns the last believed pose.
  PlanarPose Drive(double x0, double x1, const std::vector<Trunk>& trunks,
                   const PlanarPose& drift) {
    PlanarPose believed;
    for (double x = x0; x <= x1 + 1e-9; x += 1) {
      const PlanarPose truth{x, 0, 0};
      believed = Compose(drift, truth);
      map_.AddKeyFrame(key_frame_++, believed, path_m_, Observe(trunks, truth, &rng_));
      path_m_ += 1;
    }
    return believed;
  }

  LandmarkMap map_{LandmarkMapOptions{}};
  std::size_t key_frame_ = 0;
  double path_m_ = 0;
  std::mt19937 rng_{11};
};

TEST_F(LandmarkMapTest, TracksTrunksAcrossKeyFrames) {
  Drive(-5, 5, Constellation({0, 0}), {});
  // Seven trunks, each seen from many key frames, none duplicated.
  EXPECT_EQ(map_.graph_landmarks(), 7U);
  for (const Landmark& l : map_.landmarks()) EXPECT_GE(l.observations, 5U);
}

TEST_F(LandmarkMapTest, RecognisesAPlaceAfterDriftAndProposesTheCorrection) {
  const std::vector<Trunk> trunks = Constellation({0, 0});
  Drive(-5, 5, trunks, {});
  Drive(6, 100, {}, {});  // a long excursion with nothing round in sight
  // Back at the trunks, 1.5 m and 2 degrees off.
  const PlanarPose drift{1.2, -0.9, 2 * M_PI / 180};
  const PlanarPose here = Drive(-4, 2, trunks, drift);
  const auto loop = map_.FindLoop(here, path_m_, {});
  ASSERT_TRUE(loop.has_value());
  EXPECT_GE(loop->matches.size(), 5U);
  // The transform undoes the drift.
  const PlanarPose residual = Compose(loop->T_old_local, drift);
  EXPECT_LT(std::hypot(residual.x_m, residual.y_m), 0.05);
  EXPECT_LT(std::abs(residual.theta_rad), 0.01);
  map_.Merge(*loop);
  EXPECT_EQ(map_.graph_landmarks(), 7U);  // the new sightings are the old trunks now
}

TEST_F(LandmarkMapTest, RejectsATwinConstellationFurtherAwayThanTheDriftCanBe) {
  // Two identical constellations 30 m apart; the robot saw the first, drove 40 m, and now sees
  // the second where it believes it is (no drift): a view-independent match fits perfectly,
  // but only by moving the robot 30 m, far beyond what 40 m of path can have drifted.
  Drive(-5, 5, Constellation({0, 0}), {});
  Drive(6, 24, {}, {});
  const PlanarPose here = Drive(25, 35, Constellation({30, 0}), {});
  // The new landmarks are new: tracking never associates them with the old (30 m apart).
  EXPECT_EQ(map_.graph_landmarks(), 14U);
  EXPECT_FALSE(map_.FindLoop(here, path_m_, {}).has_value());
}

TEST(LandmarkMapAmbiguityTest, RejectsAMatchThatTwoOldPlacesFitAsWell) {
  // The park holds the same constellation twice, 30 m apart, and the robot, back after a long
  // excursion, believes it is half way between them: with a drift bound wide enough for both,
  // either copy explains the trunks it sees, so neither may close the loop.
  LandmarkMapOptions options;
  options.max_correction_m = 25;
  options.max_search_range_m = 60;
  LandmarkMap map(options);
  std::size_t key_frame = 0;
  double path_m = 0;
  std::mt19937 rng(3);
  std::vector<Trunk> both = Constellation({0, 0});
  for (const Trunk& t : Constellation({30, 0})) both.push_back(t);
  for (double x = -5; x <= 35; x += 1) {
    map.AddKeyFrame(key_frame++, {x, 0, 0}, path_m, Observe(both, {x, 0, 0}, &rng));
    path_m += 1;
  }
  path_m += 100;
  PlanarPose here;
  for (double x = -3; x <= 3; x += 1) {
    here = {x + 15, 0, 0};
    map.AddKeyFrame(key_frame++, here, path_m, Observe(Constellation({0, 0}), {x, 0, 0}, &rng));
    path_m += 1;
  }
  EXPECT_FALSE(map.FindLoop(here, path_m, {}).has_value());
  // With one copy only, the same sighting closes the loop.
  LandmarkMap single(options);
  key_frame = 0;
  path_m = 0;
  for (double x = -5; x <= 5; x += 1) {
    single.AddKeyFrame(key_frame++, {x, 0, 0}, path_m,
                       Observe(Constellation({0, 0}), {x, 0, 0}, &rng));
    path_m += 1;
  }
  path_m += 100;
  for (double x = -3; x <= 3; x += 1) {
    here = {x + 15, 0, 0};
    single.AddKeyFrame(key_frame++, here, path_m, Observe(Constellation({0, 0}), {x, 0, 0}, &rng));
    path_m += 1;
  }
  EXPECT_TRUE(single.FindLoop(here, path_m, {}).has_value());
}

TEST_F(LandmarkMapTest, ARowOfTreesFixesNothingAlongTheRow) {
  // Trees every 5 m along a path: any shift by 5 m matches as well; the inliers are collinear.
  std::vector<Trunk> row;
  for (int i = -6; i <= 6; ++i) row.push_back({{5.0 * i, 6}, 0.25});
  Drive(-5, 5, row, {});
  Drive(6, 100, {}, {});
  const PlanarPose here = Drive(-4, 2, row, {0.5, 0, 0});
  EXPECT_FALSE(map_.FindLoop(here, path_m_, {}).has_value());
}

TEST(LandmarkMapGraphTest, KeepsRoundObstaclesWhoseRadiusChangesWithTheViewOutOfTheGraph) {
  // A trunk fits the same circle from every side; a bush or a rock fits a different one from each,
  // and its centre moves with the view. 10 key frames see both at the same place.
  const auto survey = [](double max_graph_radius_spread_m) {
    LandmarkMapOptions options;
    options.max_graph_radius_spread_m = max_graph_radius_spread_m;
    LandmarkMap map(options);
    std::mt19937 rng(5);
    std::normal_distribution<double> trunk_noise(0, 0.008);          // 8 mm
    std::uniform_real_distribution<double> bush_radius(0.17, 0.27);  // 29 mm
    for (std::size_t k = 0; k < 10; ++k) {
      LandmarkObservation trunk, bush;
      trunk.centre_base = {4, 1};
      trunk.radius_m = 0.25 + trunk_noise(rng);
      bush.centre_base = {4, -3};
      bush.radius_m = bush_radius(rng);
      for (LandmarkObservation* o : {&trunk, &bush}) {
        o->covariance_base = 0.02 * 0.02 * Eigen::Matrix2d::Identity();
      }
      map.AddKeyFrame(k, {}, static_cast<double>(k) * 0.1, {trunk, bush});
    }
    return map;
  };
  const LandmarkMap gated = survey(0.015);
  ASSERT_EQ(gated.landmarks().size(), 2U);
  EXPECT_TRUE(gated.InGraph(gated.landmarks()[0]));
  EXPECT_FALSE(gated.InGraph(gated.landmarks()[1]));
  EXPECT_EQ(gated.graph_landmarks(), 1U);
  EXPECT_EQ(survey(0.05).graph_landmarks(), 2U);
}

}  // namespace
}  // namespace littermap::reconstruct

// Loops that tie the same two stretches of a path must agree with each other through the
// tracker's relative poses; the one that does not is dropped.

#include "reconstruct/loop_consistency.hpp"

#include <numbers>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "support/angles.hpp"

namespace littermap::reconstruct {
namespace {

using test::kDeg;

// A survey out along a lane and back along the next, 1 m aside: pose i and pose 59 - i are
// at the same place, facing opposite ways. The tracker's steps are edges i -> i + 1, exact, and
// held by a gyro unless `unheld` says otherwise.
struct Path {
  Path() {
    for (std::size_t i = 0; i < 60; ++i) {
      const double along = i < 30 ? static_cast<double>(i) : static_cast<double>(59 - i);
      path_length_m.push_back(static_cast<double>(i));
      T_world.push_back(i < 30 ? PlanarPose{along, 0, 0} : PlanarPose{along, 1, std::numbers::pi});
      if (i > 0) AddEdge(i - 1, i, false, {});
    }
  }
  // A loop from -> to measured with `error` on top of the truth; returns its edge index.
  std::size_t AddLoop(std::size_t from, std::size_t to, double strength_ratio,
                      const PlanarPose& error = {}) {
    AddEdge(from, to, true, error);
    strength.back() = strength_ratio;
    return edges.size() - 1;
  }
  void AddEdge(std::size_t from, std::size_t to, bool loop, const PlanarPose& error) {
    PoseGraphEdge edge;
    edge.from = from;
    edge.to = to;
    edge.T_from_to = Compose(Between(T_world[from], T_world[to]), error);
    edge.loop = loop;
    edges.push_back(edge);
    strength.push_back(0);
  }
  std::vector<std::size_t> Inconsistent(const LoopConsistencyOptions& options = {}) const {
    return InconsistentLoops(
        edges, path_length_m, strength,
        [&](std::size_t a, std::size_t b) { return !(a <= unheld && unheld < b); }, options);
  }
  std::size_t unheld = 1000;  // a step (unheld -> unheld + 1) the gyro did not turn

  std::vector<PlanarPose> T_world;
  std::vector<double> path_length_m;
  std::vector<PoseGraphEdge> edges;
  std::vector<double> strength;
};

const PlanarPose kWrong{0.05, 0.14, 2 * kDeg};  // a dock's trunks matched from another side

TEST(LoopConsistency, TheLoopThatDisagreesWithTheOthersIsDropped) {
  Path path;
  path.AddLoop(2, 56, 0.85);
  const std::size_t wrong = path.AddLoop(1, 55, 0.65, kWrong);
  path.AddLoop(0, 58, 0.9, {0.02, -0.01, 0.3 * kDeg});  // true loops' own errors
  path.AddLoop(3, 57, 1.0, {-0.01, 0.02, -0.3 * kDeg});
  EXPECT_EQ(path.Inconsistent(), std::vector<std::size_t>{wrong});
}

TEST(LoopConsistency, OfTwoThatDisagreeTheWeakerMatchIsDropped) {
  Path path;
  const std::size_t weak = path.AddLoop(2, 56, 0.65);
  path.AddLoop(1, 55, 0.95, kWrong);
  // Nothing else to tell which is wrong: the weaker overlay goes, even where it was the true one.
  EXPECT_EQ(path.Inconsistent(), std::vector<std::size_t>{weak});
}

TEST(LoopConsistency, TrueLoopsWithinTheirOwnErrorsAllStay) {
  Path path;
  for (std::size_t k = 0; k < 8; ++k) {
    const double sign = k % 2 == 0 ? 1 : -1;
    path.AddLoop(k, 58 - k, 0.7, {0.02 * sign, -0.02 * sign, 0.4 * kDeg * sign});
  }
  EXPECT_TRUE(path.Inconsistent().empty());
}

TEST(LoopConsistency, LoopsBetweenStretchesFarApartAreNotCompared) {
  Path path;
  path.AddLoop(0, 59, 0.9);
  // 20 m from the other loop's ends along the path, and 5 degrees off it: not compared.
  path.AddLoop(20, 39, 0.65, {0, 0.2, 5 * kDeg});
  EXPECT_TRUE(path.Inconsistent().empty());
  LoopConsistencyOptions wider;
  wider.max_stretch_m = 25;
  EXPECT_EQ(path.Inconsistent(wider).size(), 1u);
}

TEST(LoopConsistency, AStretchWithoutTheTrackersStepsIsNoEvidence) {
  Path path;
  path.edges.erase(path.edges.begin() + 55);  // the step 55 -> 56
  path.strength.erase(path.strength.begin() + 55);
  path.AddLoop(2, 56, 0.9);
  path.AddLoop(1, 55, 0.65, kWrong);
  EXPECT_TRUE(path.Inconsistent().empty());
}

TEST(LoopConsistency, OnlyStretchesAGyroHeldAreEvidence) {
  Path path;
  path.AddLoop(2, 56, 0.65);
  path.AddLoop(1, 55, 0.95, kWrong);
  path.unheld = 55;  // the step 55 -> 56: a laser alone may have turned more there
  EXPECT_TRUE(path.Inconsistent().empty());
}

TEST(LoopConsistency, NegativeBoundsAreUsageErrors) {
  LoopConsistencyOptions options;
  options.max_disagreement_rad = -1;
  EXPECT_THROW(options.Validate(), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct

// Loop closure: a true revisit is accepted with the right correction, also after drift beyond
// ICP's reach (the wide search); a false candidate (a different place) is rejected, not added to
// the graph; far along the graph a loop needs a higher matching ratio.

#include "reconstruct/loop_closer.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

Points2 PointsFrom(const std::vector<test::Segment>& walls, const PlanarPose& pose) {
  return VoxelDownsample(ScanToPoints(test::ScanFrom(walls, pose), {}, {}).points_base, 0.05);
}

// Key frames 1 m apart (path length), all seeing `walls` from the true poses, stored at the
// estimated poses (truth shifted by `drift` for the last one).
KeyFrameMap MapWithRevisit(const std::vector<test::Segment>& first_walls,
                           const std::vector<test::Segment>& last_walls, const PlanarPose& drift) {
  KeyFrameMap map({}, {});
  const std::vector<PlanarPose> truth = {{2, 2, 0},   {3, 2, 0},   {4, 2, 0},    {5, 1.5, 0},
                                         {7, 1.5, 0}, {9, 1.5, 0}, {10, 3, 1.5}, {9, 6, 3.1},
                                         {6, 6, 3.1}, {3, 6, 3.1}, {2, 4, -1.5}, {2.2, 2.1, 0.05}};
  double path = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (i > 0) path += 3;  // generous: the revisit is far back along the path
    const bool last = i + 1 == truth.size();
    const PlanarPose stored = last ? Compose(truth[i], drift) : truth[i];
    map.Add({i,
             static_cast<TimestampNs>(i),
             stored,
             PointsFrom(last ? last_walls : first_walls, truth[i]),
             path,
             {}});
  }
  return map;
}

TEST(LoopCloser, TrueRevisitIsAcceptedWithTheCorrection) {
  const auto room = test::Room();
  const PlanarPose drift{0.3, -0.2, 0.04};
  const KeyFrameMap map = MapWithRevisit(room, room, drift);
  const LoopCloser closer({});
  const LoopAttempt attempt = closer.TryClose(map, map.key_frames().size() - 1);
  ASSERT_EQ(attempt.verdict, LoopVerdict::kAccepted);
  ASSERT_TRUE(attempt.edge.has_value());
  EXPECT_EQ(attempt.edge->to, map.key_frames().size() - 1);
  // The edge places the last key frame at its true pose (2.2, 2.1, 0.05) relative to the
  // candidate's (true) pose.
  const PlanarPose T_world_last =
      Compose(map.key_frames()[attempt.edge->from].T_world_base, attempt.edge->T_from_to);
  EXPECT_NEAR(T_world_last.x_m, 2.2, 0.01);
  EXPECT_NEAR(T_world_last.y_m, 2.1, 0.01);
  EXPECT_NEAR(T_world_last.theta_rad, 0.05, 0.005);
}

TEST(LoopCloser, FalseCandidateIsRejected) {
  // The last key frame sees a different building (a long corridor), at the place of the first.
  std::vector<test::Segment> corridor = {
      {{-20, 1}, {30, 1}}, {{-20, 3.2}, {30, 3.2}}, {{4, 3.2}, {4, 6}}, {{6, 1}, {6, -3}}};
  const KeyFrameMap map = MapWithRevisit(test::Room(), corridor, {});
  const LoopCloser closer({});
  const LoopAttempt attempt = closer.TryClose(map, map.key_frames().size() - 1);
  EXPECT_NE(attempt.verdict, LoopVerdict::kAccepted);
  EXPECT_NE(attempt.verdict, LoopVerdict::kNoCandidate);
  EXPECT_FALSE(attempt.edge.has_value());
}

// Distance of every key frame from the last along the pose graph, as if no loop had been closed
// for a long excursion.
std::vector<double> FarAlongTheGraph(const KeyFrameMap& map, double distance_m) {
  std::vector<double> distances(map.key_frames().size(), distance_m);
  distances.back() = 0;
  return distances;
}

TEST(LoopCloser, WideSearchFindsARevisitBeyondIcpReach) {
  // 2.9 m and 8.6 degrees of drift after a long excursion: outside ICP's basin and the guesses
  // of the nearest-candidate search, inside the correlative window for 300 m along the graph.
  const auto room = test::Room();
  const PlanarPose drift{2.5, -1.5, 0.15};
  const KeyFrameMap map = MapWithRevisit(room, room, drift);
  const std::size_t last = map.key_frames().size() - 1;
  const std::vector<double> graph = FarAlongTheGraph(map, 300);
  const LoopCloser closer({});
  EXPECT_NE(closer.TryClose(map, last, graph, /*wide=*/false).verdict, LoopVerdict::kAccepted);
  const LoopAttempt attempt = closer.TryClose(map, last, graph, /*wide=*/true);
  ASSERT_EQ(attempt.verdict, LoopVerdict::kAccepted);
  const PlanarPose T_world_last =
      Compose(map.key_frames()[attempt.edge->from].T_world_base, attempt.edge->T_from_to);
  EXPECT_NEAR(T_world_last.x_m, 2.2, 0.01);
  EXPECT_NEAR(T_world_last.y_m, 2.1, 0.01);
  EXPECT_NEAR(T_world_last.theta_rad, 0.05, 0.005);
}

TEST(LoopCloser, FarCandidateNeedsMoreEvidence) {
  // The right place, but a screen right in front of the robot hides a quarter of the room: a
  // matching ratio good enough for a loop close along the graph (small drift, little room for
  // a look-alike), not for one far along it, where a place that only resembles the old one
  // (a facade slid along itself) is likelier: the false loop of freiburg-campus, seed 2.
  const auto room = test::Room();
  auto cluttered = room;
  cluttered.push_back({{3.2, 1.0}, {3.2, 3.4}});
  const KeyFrameMap map = MapWithRevisit(room, cluttered, {0.1, -0.05, 0.01});
  const std::size_t last = map.key_frames().size() - 1;
  const LoopCloser closer({});
  const LoopAttempt near = closer.TryClose(map, last, FarAlongTheGraph(map, 40));
  ASSERT_EQ(near.verdict, LoopVerdict::kAccepted);
  EXPECT_LT(near.match.inlier_ratio, LoopCloserOptions{}.min_wide_matching_ratio);
  const LoopAttempt far = closer.TryClose(map, last, FarAlongTheGraph(map, 400));
  EXPECT_EQ(far.verdict, LoopVerdict::kRejectedMatch);
  EXPECT_FALSE(far.edge.has_value());
}

TEST(LoopCloser, CorrectionBeyondPlausibleDriftIsRejected) {
  // The right place, but the estimate claims to be 3 m and 0.6 rad off after only 33 m of path,
  // more than tracking drifts: a match there would be a coincidence.
  const auto room = test::Room();
  LoopCloserOptions options;
  options.max_correction_m = 0.1;
  options.max_correction_per_m = 0.001;
  const KeyFrameMap map = MapWithRevisit(room, room, {0.5, 0.3, 0.05});
  const LoopAttempt attempt = LoopCloser(options).TryClose(map, map.key_frames().size() - 1);
  EXPECT_EQ(attempt.verdict, LoopVerdict::kRejectedDisagreement);
}

}  // namespace
}  // namespace littermap::reconstruct

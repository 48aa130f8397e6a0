// Correlative scan matching (reconstruct/correlative_matcher.hpp): one search for a scan of the
// synthetic room 2.3 m and 8.6 degrees from the guess, over windows of 3 and 8 m (+-0.3 rad),
// at branch-and-bound depths 0 (every pose scored), 3 and 7 (Cartographer's default), without a
// minimum score and with the loop closer's (0.4: min_score_pct 40). Counters: the window's
// poses, and the candidates the search scored (bounds above the fine level, fine poses). Every
// row finds the same pose.

#include <benchmark/benchmark.h>

#include "reconstruct/correlative_matcher.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {
namespace {

// Ten by eight metres of walls with a pillar, sampled every 2 cm: what a scanner at `pose` sees
// of it, in the scanner's frame (points within 12 m, one per 0.5 degrees).
Points2 RoomScan(const PlanarPose& pose) {
  struct Box {
    Eigen::Vector2d low, high;
  };
  const Box boxes[] = {{{0, 0}, {10, 8}}, {{5, 3}, {5.6, 3.6}}};
  Points2 points;
  for (int k = 0; k < 720; ++k) {
    const double angle = pose.theta_rad + k * 3.14159265358979 / 360;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    const Eigen::Vector2d origin(pose.x_m, pose.y_m);
    double nearest = 12;
    for (const Box& box : boxes) {
      for (int axis = 0; axis < 2; ++axis) {
        for (const double wall : {box.low[axis], box.high[axis]}) {
          if (std::abs(direction[axis]) < 1e-9) continue;
          const double t = (wall - origin[axis]) / direction[axis];
          const Eigen::Vector2d hit = origin + t * direction;
          const int other = 1 - axis;
          if (t > 0.05 && t < nearest && hit[other] >= box.low[other] - 1e-9 &&
              hit[other] <= box.high[other] + 1e-9) {
            nearest = t;
          }
        }
      }
    }
    if (nearest < 12) points.push_back(Transform(Inverse(pose), origin + nearest * direction));
  }
  return points;
}

void BM_Correlative(benchmark::State& state) {
  const double window_m = static_cast<double>(state.range(0));
  CorrelativeOptions options;
  options.max_branch_and_bound_depth = static_cast<int>(state.range(1));
  options.min_score = static_cast<double>(state.range(2)) / 100;
  const PlanarPose T_world_target{3, 2, 0};
  Points2 target;
  for (const Eigen::Vector2d& p : RoomScan(T_world_target)) {
    target.push_back(Transform(T_world_target, p));
  }
  const Points2 source = RoomScan({6.5, 4.2, 0.2});
  const PlanarPose guess{4.5, 3.0, 0.05};
  CorrelativeResult result;
  for (auto _ : state) {
    result = MatchCorrelative(source, target, guess, window_m, 0.3, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["window_poses"] = static_cast<double>(result.window_poses);
  state.counters["bounds"] = static_cast<double>(result.bound_evaluations);
  state.counters["fine"] = static_cast<double>(result.fine_evaluations);
  state.counters["score"] = result.score;
}
BENCHMARK(BM_Correlative)
    ->ArgNames({"window_m", "depth", "min_score_pct"})
    ->ArgsProduct({{3, 8}, {0, 3, 7}, {0, 40}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace littermap::reconstruct

BENCHMARK_MAIN();

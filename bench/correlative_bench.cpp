// Correlative scan matching (reconstruct/correlative_matcher.hpp): one search for a scan of the
// tests' synthetic room (tests/reconstruct/synthetic_world.hpp) 2.3 m and 8.6 degrees from the
// guess, as in CorrelativeMatcher.FindsAPoseFarFromTheGuess, over windows of 3 and 8 m (+-0.3 rad),
// at branch-and-bound depths 0 (every pose scored), 3 and 7 (Cartographer's default), without a
// minimum score and with the loop closer's (0.4: min_score_pct 40). Counters: the window's
// poses, and the candidates the search scored (bounds above the fine level, fine poses). Every
// row finds the same pose.

#include <benchmark/benchmark.h>

#include "reconstruct/correlative_matcher.hpp"
#include "reconstruct/synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

void BM_Correlative(benchmark::State& state) {
  const double window_m = static_cast<double>(state.range(0));
  CorrelativeOptions options;
  options.max_branch_and_bound_depth = static_cast<int>(state.range(1));
  options.min_score = static_cast<double>(state.range(2)) / 100;
  const PlanarPose T_world_target{3, 2, 0};
  const Points2 target = TransformPoints(T_world_target, test::RoomPoints(T_world_target));
  const Points2 source = test::RoomPoints({6.5, 4.2, 0.2});
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

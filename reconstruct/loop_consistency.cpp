#include "reconstruct/loop_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

// The tracker's relative poses between consecutive poses, from the sequential edges.
class Stretches {
 public:
  Stretches(const std::vector<PoseGraphEdge>& edges, std::size_t poses) : steps_(poses) {
    for (const PoseGraphEdge& edge : edges) {
      if (IsTrackerStep(edge) && edge.to < poses && !steps_[edge.from]) {
        steps_[edge.from] = edge.T_from_to;
      }
    }
  }

  // T_a_b along the path, or nothing where a step is missing.
  std::optional<PlanarPose> Between(std::size_t a, std::size_t b) const {
    PlanarPose T_low_high;
    for (std::size_t i = std::min(a, b); i < std::max(a, b); ++i) {
      if (!steps_[i]) return std::nullopt;
      T_low_high = Compose(T_low_high, *steps_[i]);
    }
    return a <= b ? T_low_high : Inverse(T_low_high);
  }

 private:
  std::vector<std::optional<PlanarPose>> steps_;  // steps_[i]: T_i_(i+1)
};

}  // namespace

void LoopConsistencyOptions::Validate() const {
  if (!(max_stretch_m >= 0) || !(max_disagreement_m >= 0) || !(max_disagreement_per_m >= 0) ||
      !(max_disagreement_rad >= 0) || !(max_disagreement_rad_per_m >= 0)) {
    throw UsageError("loop consistency: the stretch and the disagreement bounds must be >= 0");
  }
}

std::vector<std::size_t> InconsistentLoops(
    const std::vector<PoseGraphEdge>& edges, const std::vector<double>& path_length_m,
    const std::vector<double>& strength, const std::function<bool(std::size_t, std::size_t)>& held,
    const LoopConsistencyOptions& options) {
  const Stretches stretches(edges, path_length_m.size());
  std::vector<std::size_t> loops;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i].loop && edges[i].from < path_length_m.size() &&
        edges[i].to < path_length_m.size()) {
      loops.push_back(i);
    }
  }
  // disagree[k]: the loops (positions in `loops`) loop k disagrees with.
  std::vector<std::vector<std::size_t>> disagree(loops.size());
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const PoseGraphEdge& one = edges[loops[k]];
    for (std::size_t l = k + 1; l < loops.size(); ++l) {
      const PoseGraphEdge& other = edges[loops[l]];
      const double earlier_m = std::abs(path_length_m[one.from] - path_length_m[other.from]);
      const double later_m = std::abs(path_length_m[one.to] - path_length_m[other.to]);
      if (earlier_m > options.max_stretch_m || later_m > options.max_stretch_m ||
          !held(std::min(one.from, other.from), std::max(one.from, other.from)) ||
          !held(std::min(one.to, other.to), std::max(one.to, other.to))) {
        continue;
      }
      const std::optional<PlanarPose> earlier = stretches.Between(one.from, other.from);
      const std::optional<PlanarPose> later = stretches.Between(one.to, other.to);
      if (!earlier || !later) continue;
      // Both give the pose of other.to in the frame of one.from.
      const PlanarPose miss =
          littermap::Between(Compose(one.T_from_to, *later), Compose(*earlier, other.T_from_to));
      const double stretch_m = earlier_m + later_m;
      if (std::hypot(miss.x_m, miss.y_m) >
              options.max_disagreement_m + options.max_disagreement_per_m * stretch_m ||
          std::abs(miss.theta_rad) >
              options.max_disagreement_rad + options.max_disagreement_rad_per_m * stretch_m) {
        disagree[k].push_back(l);
        disagree[l].push_back(k);
      }
    }
  }
  std::vector<bool> dropped(loops.size(), false);
  const auto count = [&](std::size_t k) {
    return std::count_if(disagree[k].begin(), disagree[k].end(),
                         [&](std::size_t l) { return !dropped[l]; });
  };
  std::vector<std::size_t> order;
  for (;;) {
    std::optional<std::size_t> worst;
    for (std::size_t k = 0; k < loops.size(); ++k) {
      if (dropped[k] || count(k) == 0) continue;
      if (!worst || count(k) > count(*worst) ||
          (count(k) == count(*worst) && strength[loops[k]] < strength[loops[*worst]])) {
        worst = k;
      }
    }
    if (!worst) return order;
    dropped[*worst] = true;
    order.push_back(loops[*worst]);
  }
}

}  // namespace littermap::reconstruct

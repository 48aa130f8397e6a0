#include "reconstruct/loop_closer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

bool Better(const IcpResult& a, const IcpResult& b) {
  if (a.converged != b.converged) return a.converged;
  return a.inlier_ratio > b.inlier_ratio;
}

}  // namespace

void LoopCloserOptions::Validate() const {
  icp.Validate();
  if (!(search_radius_m > 0) || !(min_path_separation_m >= 0)) {
    throw UsageError("loop closure: search_radius_m must be > 0, min_path_separation_m >= 0");
  }
  if (!(min_matching_ratio > 0 && min_matching_ratio <= 1)) {
    throw UsageError("loop closure: min_matching_ratio must be in (0, 1]");
  }
}

LoopCloser::LoopCloser(const LoopCloserOptions& options) : options_(options) {
  options_.Validate();
}

LoopAttempt LoopCloser::TryClose(const KeyFrameMap& map, std::size_t current) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < current; ++j) {
    if (now.path_length_m - frames[j].path_length_m < options_.min_path_separation_m) break;
    const double distance = std::hypot(frames[j].T_world_base.x_m - now.T_world_base.x_m,
                                       frames[j].T_world_base.y_m - now.T_world_base.y_m);
    if (distance <= options_.search_radius_m && distance < best_distance) {
      best_distance = distance;
      best = j;
    }
  }
  if (!std::isfinite(best_distance)) return {};
  return TryCandidate(map, current, best);
}

LoopAttempt LoopCloser::TryCandidate(const KeyFrameMap& map, std::size_t current,
                                     std::size_t candidate) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  LoopAttempt attempt;
  attempt.candidate = candidate;
  // The submap stops short of the recent path, so the loop is checked against old map only.
  std::size_t last = std::min(candidate + options_.submap_half_window, current - 1);
  while (last > candidate &&
         now.path_length_m - frames[last].path_length_m < options_.min_path_separation_m) {
    --last;
  }
  const std::size_t first =
      candidate > options_.submap_half_window ? candidate - options_.submap_half_window : 0;
  MapPoints submap = map.WorldPoints(first, last);
  const IcpTarget target(std::move(submap.points), std::move(submap.normals));

  IcpResult match = MatchIcp(now.points_base, target, now.T_world_base, options_.icp);
  if (!(match.converged && match.inlier_ratio >= options_.min_matching_ratio)) {
    // A small grid of initial guesses around the estimate (drift moved the old map), tried
    // with every third point; the best is refined with all of them.
    Points2 sparse;
    for (std::size_t i = 0; i < now.points_base.size(); i += 3)
      sparse.push_back(now.points_base[i]);
    IcpResult best_sparse;
    for (int ix = -1; ix <= 1; ++ix) {
      for (int iy = -1; iy <= 1; ++iy) {
        for (int it = -1; it <= 1; ++it) {
          if (ix == 0 && iy == 0 && it == 0) continue;
          const PlanarPose guess{now.T_world_base.x_m + ix * options_.guess_step_m,
                                 now.T_world_base.y_m + iy * options_.guess_step_m,
                                 now.T_world_base.theta_rad + it * options_.guess_step_rad};
          const IcpResult other = MatchIcp(sparse, target, guess, options_.icp);
          if (Better(other, best_sparse)) best_sparse = other;
        }
      }
    }
    if (best_sparse.converged) {
      const IcpResult refined =
          MatchIcp(now.points_base, target, best_sparse.T_target_source, options_.icp);
      if (Better(refined, match)) match = refined;
    }
  }
  attempt.match = match;
  if (!match.converged || match.inlier_ratio < options_.min_matching_ratio ||
      match.rms_residual_m > options_.max_rms_residual_m) {
    attempt.verdict = LoopVerdict::kRejectedMatch;
    return attempt;
  }
  // Agreement with the graph: the correction must be explainable by tracking drift.
  const double path = now.path_length_m - frames[candidate].path_length_m;
  const PlanarPose correction = Between(now.T_world_base, match.T_target_source);
  if (std::hypot(correction.x_m, correction.y_m) >
          options_.max_correction_m + options_.max_correction_per_m * path ||
      std::abs(correction.theta_rad) >
          options_.max_correction_rad + options_.max_correction_rad_per_m * path) {
    attempt.verdict = LoopVerdict::kRejectedDisagreement;
    return attempt;
  }
  PoseGraphEdge edge;
  edge.from = candidate;
  edge.to = current;
  edge.T_from_to = Between(frames[candidate].T_world_base, match.T_target_source);
  edge.information = match.information;  // world frame; see EdgeInformation
  edge.loop = true;
  attempt.edge = edge;
  attempt.verdict = LoopVerdict::kAccepted;
  return attempt;
}

}  // namespace littermap::reconstruct

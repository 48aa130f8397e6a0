#include "reconstruct/loop_closer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

// Distance of key frame j from `current` along the pose graph, or along the path without one.
double GraphDistance(const std::vector<KeyFrame>& frames, std::size_t current, std::size_t j,
                     const std::vector<double>& graph_distance_m) {
  return j < graph_distance_m.size() ? graph_distance_m[j]
                                     : frames[current].path_length_m - frames[j].path_length_m;
}

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
  correlative.Validate();
  if (!(wide_window_m > 0) || !(wide_window_rad > 0) || !(max_wide_window_m > 0) ||
      !(max_wide_window_rad > 0) || wide_window_per_m < 0 || wide_window_rad_per_m < 0) {
    throw UsageError("loop closure: wide search windows must be > 0");
  }
  if (!(min_wide_matching_ratio > 0 && min_wide_matching_ratio <= 1) ||
      !(min_correlative_score >= 0 && min_correlative_score <= 1) || far_graph_distance_m < 0) {
    throw UsageError(
        "loop closure: min_wide_matching_ratio must be in (0, 1], min_correlative_score in "
        "[0, 1], far_graph_distance_m >= 0");
  }
}

LoopCloser::LoopCloser(const LoopCloserOptions& options) : options_(options) {
  options_.Validate();
}

LoopAttempt LoopCloser::TryClose(const KeyFrameMap& map, std::size_t current,
                                 const std::vector<double>& graph_distance_m, bool wide) const {
  LoopAttempt attempt = TryNearest(map, current, graph_distance_m);
  if (attempt.verdict == LoopVerdict::kAccepted || !wide) return attempt;
  LoopAttempt wide_attempt = TryWide(map, current, graph_distance_m);
  return wide_attempt.verdict == LoopVerdict::kNoCandidate ? attempt : wide_attempt;
}

LoopAttempt LoopCloser::TryNearest(const KeyFrameMap& map, std::size_t current,
                                   const std::vector<double>& graph_distance_m) const {
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
  const bool far =
      GraphDistance(frames, current, best, graph_distance_m) >= options_.far_graph_distance_m;
  return TryCandidate(map, current, best,
                      far ? options_.min_wide_matching_ratio : options_.min_matching_ratio);
}

Points2 LoopCloser::SourcePoints(const KeyFrameMap& map, std::size_t current) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  if (now.points_base.size() >= options_.min_source_points) return now.points_base;
  Points2 points = now.points_base;
  const PlanarPose T_base_world = Inverse(now.T_world_base);
  for (std::size_t j = current; j-- > 0 && points.size() < options_.min_source_points;) {
    if (now.path_length_m - frames[j].path_length_m > options_.max_source_path_m) break;
    const PlanarPose T_now_j = Compose(T_base_world, frames[j].T_world_base);
    for (const Eigen::Vector2d& p : frames[j].points_base) points.push_back(Transform(T_now_j, p));
  }
  return VoxelDownsample(points, options_.source_voxel_size_m);
}

LoopAttempt LoopCloser::TryCandidate(const KeyFrameMap& map, std::size_t current,
                                     std::size_t candidate, double min_ratio) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
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

  const Points2 source = SourcePoints(map, current);
  IcpResult match = MatchIcp(source, target, now.T_world_base, options_.icp);
  if (!(match.converged && match.inlier_ratio >= min_ratio)) {
    // A small grid of initial guesses around the estimate (drift moved the old map), tried
    // with every third point; the best is refined with all of them.
    Points2 sparse;
    for (std::size_t i = 0; i < source.size(); i += 3) sparse.push_back(source[i]);
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
      const IcpResult refined = MatchIcp(source, target, best_sparse.T_target_source, options_.icp);
      if (Better(refined, match)) match = refined;
    }
  }
  return Judge(map, current, candidate, match, min_ratio, {});
}

LoopAttempt LoopCloser::TryWide(const KeyFrameMap& map, std::size_t current,
                                const std::vector<double>& graph_distance_m) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  // Every earlier key frame whose view can overlap the scan within the drift it can have; the
  // window covers the largest of those drifts.
  std::vector<std::size_t> reachable;
  double window_m = 0, window_rad = 0;
  for (std::size_t j = 0; j < current; ++j) {
    if (now.path_length_m - frames[j].path_length_m < options_.min_path_separation_m) break;
    const double graph_m = GraphDistance(frames, current, j, graph_distance_m);
    const double drift_m = std::min(options_.max_wide_window_m,
                                    options_.wide_window_m + options_.wide_window_per_m * graph_m);
    const double distance = std::hypot(frames[j].T_world_base.x_m - now.T_world_base.x_m,
                                       frames[j].T_world_base.y_m - now.T_world_base.y_m);
    if (drift_m < options_.min_wide_window_m || distance > drift_m + options_.search_radius_m) {
      continue;
    }
    reachable.push_back(j);
    window_m = std::max(window_m, drift_m);
    window_rad = std::max(
        window_rad, std::min(options_.max_wide_window_rad,
                             options_.wide_window_rad + options_.wide_window_rad_per_m * graph_m));
  }
  if (reachable.empty()) return {};
  MapPoints submap = map.WorldPoints(reachable);
  const Points2 source = SourcePoints(map, current);
  const CorrelativeResult coarse = MatchCorrelative(source, submap.points, now.T_world_base,
                                                    window_m, window_rad, options_.correlative);
  LoopAttempt attempt;
  attempt.candidate = reachable.front();
  if (!coarse.found || coarse.score < options_.min_correlative_score) {
    attempt.verdict = LoopVerdict::kRejectedMatch;
    return attempt;
  }
  const IcpTarget target(std::move(submap.points), std::move(submap.normals));
  const IcpResult match = MatchIcp(source, target, coarse.T_target_source, options_.icp);
  // The edge starts at the reachable key frame nearest to the matched pose.
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t j : reachable) {
    const double distance = std::hypot(frames[j].T_world_base.x_m - match.T_target_source.x_m,
                                       frames[j].T_world_base.y_m - match.T_target_source.y_m);
    if (distance < nearest) {
      nearest = distance;
      attempt.candidate = j;
    }
  }
  return Judge(map, current, attempt.candidate, match, options_.min_wide_matching_ratio,
               {window_m, window_m, window_rad});
}

LoopAttempt LoopCloser::Judge(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                              const IcpResult& match, double min_ratio,
                              const PlanarPose& window) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  LoopAttempt attempt;
  attempt.candidate = candidate;
  attempt.match = match;
  if (!match.converged || match.inlier_ratio < min_ratio ||
      match.rms_residual_m > options_.max_rms_residual_m) {
    attempt.verdict = LoopVerdict::kRejectedMatch;
    return attempt;
  }
  // Agreement with the graph: the correction must be explainable by tracking drift (for a wide
  // match: lie in the window searched, which the drift bounds, plus ICP's last step).
  const double path = now.path_length_m - frames[candidate].path_length_m;
  const PlanarPose correction = Between(now.T_world_base, match.T_target_source);
  const double max_m = std::max(options_.MaxCorrectionM(path),
                                std::sqrt(2.0) * window.x_m + options_.correlative.cell_size_m);
  const double max_rad =
      std::max(options_.MaxCorrectionRad(path), window.theta_rad + options_.guess_step_rad);
  if (std::hypot(correction.x_m, correction.y_m) > max_m ||
      std::abs(correction.theta_rad) > max_rad) {
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

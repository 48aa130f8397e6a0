#include "reconstruct/loop_closer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

// Distance of key frame j from `current` along the pose graph, or along the path without one.
double GraphDistance(const std::vector<KeyFrame>& frames, std::size_t current, std::size_t j,
                     const GraphReach& reach) {
  return j < reach.distance_m.size() ? reach.distance_m[j]
                                     : frames[current].path_length_m - frames[j].path_length_m;
}

bool Better(const IcpResult& a, const IcpResult& b) {
  if (a.converged != b.converged) return a.converged;
  return a.inlier_ratio > b.inlier_ratio;
}

// The key frame of `candidates` nearest to `position` (candidates not empty).
std::size_t NearestOf(const KeyFrameMap& map, const std::vector<std::size_t>& candidates,
                      const PlanarPose& position) {
  const auto& frames = map.key_frames();
  std::size_t best = candidates.front();
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t j : candidates) {
    const double distance = std::hypot(frames[j].T_world_base.x_m - position.x_m,
                                       frames[j].T_world_base.y_m - position.y_m);
    if (distance < nearest) {
      nearest = distance;
      best = j;
    }
  }
  return best;
}

// Standard deviation of a pose estimate with this information along its least constrained
// direction, the heading scaled to metres by lever_arm_m; infinite if a direction is free.
double WeakestSigmaM(const Eigen::Matrix3d& information, double lever_arm_m) {
  const Eigen::Matrix3d scale = Eigen::Vector3d(1, 1, 1 / lever_arm_m).asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scale * information * scale,
                                                              Eigen::EigenvaluesOnly);
  const double weakest = solver.eigenvalues()(0);
  return weakest > 0 ? 1 / std::sqrt(weakest) : std::numeric_limits<double>::infinity();
}

}  // namespace

GraphReach ReachFrom(std::size_t key_frames, const std::vector<PoseGraphEdge>& edges,
                     std::size_t current) {
  GraphReach reach;
  reach.distance_m = GraphDistances(key_frames, edges, current);
  reach.odometry_heading_variance_rad2 = GraphDistances(
      key_frames, edges, current,
      [](const PoseGraphEdge& edge) { return edge.odometry_sigma_rad * edge.odometry_sigma_rad; });
  return reach;
}

void LoopCloserOptions::Validate() const {
  icp.Validate();
  if (!(search_radius_m > 0) || !(min_path_separation_m >= 0)) {
    throw UsageError("loop closure: search_radius_m must be > 0, min_path_separation_m >= 0");
  }
  if (!(min_matching_ratio > 0 && min_matching_ratio <= 1)) {
    throw UsageError("loop closure: min_matching_ratio must be in (0, 1]");
  }
  correlative.Validate();
  if (!(max_weakest_sigma_m > 0) || !(heading_lever_arm_m > 0)) {
    throw UsageError("loop closure: max_weakest_sigma_m and heading_lever_arm_m must be > 0");
  }
  if (!(wide_window_m > 0) || !(wide_window_rad > 0) || !(max_wide_window_m > 0) ||
      !(max_wide_window_rad > 0) || wide_window_per_m < 0 || wide_window_rad_per_m < 0) {
    throw UsageError("loop closure: wide search windows must be > 0");
  }
  if (!(odometry_drift_sigmas >= 0) || !(max_confirmation_disagreement_m >= 0) ||
      !(max_confirmation_disagreement_rad >= 0)) {
    throw UsageError(
        "loop closure: odometry_drift_sigmas and the confirmation's disagreement bounds must be "
        ">= 0");
  }
  if (!(max_gyro_disagreement_rad > 0) || !(max_gyro_disagreement_rad_per_s >= 0)) {
    throw UsageError(
        "loop closure: max_gyro_disagreement_rad must be > 0, max_gyro_disagreement_rad_per_s "
        ">= 0");
  }
  if (!(min_wide_matching_ratio > 0 && min_wide_matching_ratio <= 1) || far_graph_distance_m < 0) {
    throw UsageError(
        "loop closure: min_wide_matching_ratio must be in (0, 1], far_graph_distance_m >= 0");
  }
}

LoopCloser::LoopCloser(const LoopCloserOptions& options) : options_(options) {
  options_.Validate();
}

LoopAttempt LoopCloser::TryClose(const KeyFrameMap& map, std::size_t current,
                                 const GraphReach& reach, bool wide) const {
  LoopAttempt attempt = TryNearest(map, current, reach);
  if (attempt.verdict == LoopVerdict::kAccepted || !wide) return attempt;
  LoopAttempt wide_attempt = TryWide(map, current, reach);
  return wide_attempt.verdict == LoopVerdict::kNoCandidate ? attempt : wide_attempt;
}

std::vector<std::size_t> LoopCloser::Within(const KeyFrameMap& map, std::size_t current,
                                            const PlanarPose& position, double radius_m) const {
  const auto& frames = map.key_frames();
  std::vector<std::size_t> within;
  for (std::size_t j = 0; j < current; ++j) {
    if (frames[current].path_length_m - frames[j].path_length_m < options_.min_path_separation_m) {
      break;
    }
    if (std::hypot(frames[j].T_world_base.x_m - position.x_m,
                   frames[j].T_world_base.y_m - position.y_m) <= radius_m) {
      within.push_back(j);
    }
  }
  return within;
}

LoopAttempt LoopCloser::TryNearest(const KeyFrameMap& map, std::size_t current,
                                   const GraphReach& reach) const {
  const PlanarPose& here = map.key_frames()[current].T_world_base;
  const std::vector<std::size_t> around = Within(map, current, here, options_.search_radius_m);
  if (around.empty()) return {};
  const std::size_t best = NearestOf(map, around, here);
  const bool far =
      GraphDistance(map.key_frames(), current, best, reach) >= options_.far_graph_distance_m;
  LoopAttempt attempt = TryCandidate(map, current, best, options_.min_matching_ratio,
                                     HeadingWindowRad(map, current, best, reach));
  if (far && attempt.verdict == LoopVerdict::kAccepted &&
      attempt.match.inlier_ratio < options_.min_wide_matching_ratio) {
    attempt.verdict = LoopVerdict::kTentative;  // see confirm_within_key_frames
  }
  return attempt;
}

LoopAttempt LoopCloser::Confirm(const KeyFrameMap& map, std::size_t current,
                                const TentativeLoop& tentative) const {
  const auto& frames = map.key_frames();
  const std::size_t tentative_key_frame = tentative.attempt.edge->to;
  // Where the tentative correction puts the current key frame.
  const PlanarPose predicted =
      Compose(tentative.T_world_corrected,
              Between(frames[tentative_key_frame].T_world_base, frames[current].T_world_base));
  // Against every old key frame around there: the place may have been passed more than once, and
  // in the other direction a forward-looking scanner saw other sides of it.
  const std::vector<std::size_t> around = Within(map, current, predicted, options_.search_radius_m);
  if (around.empty()) return {};
  MapPoints submap = map.WorldPoints(around);
  const IcpTarget target(std::move(submap.points), std::move(submap.normals));
  const IcpResult match = MatchIcp(SourcePoints(map, current), target, predicted, options_.icp);
  LoopAttempt attempt;
  attempt.candidate = NearestOf(map, around, match.T_target_source);
  attempt.match = match;
  const PlanarPose moved = Between(predicted, match.T_target_source);
  if (match.converged &&
      (std::hypot(moved.x_m, moved.y_m) > options_.max_confirmation_disagreement_m ||
       std::abs(moved.theta_rad) > options_.max_confirmation_disagreement_rad)) {
    attempt.verdict = LoopVerdict::kRejectedDisagreement;
    return attempt;
  }
  return Judge(map, current, attempt.candidate, match, options_.min_matching_ratio,
               tentative.attempt.window);
}

double LoopCloser::MatchedHeadingRad(const KeyFrameMap& map, std::size_t current, std::size_t j,
                                     const GraphReach& reach) const {
  return options_.wide_window_rad +
         options_.wide_window_rad_per_m * GraphDistance(map.key_frames(), current, j, reach);
}

double LoopCloser::OdometryHeadingRad(std::size_t j, const GraphReach& reach) const {
  return j < reach.odometry_heading_variance_rad2.size()
             ? options_.odometry_drift_sigmas * std::sqrt(reach.odometry_heading_variance_rad2[j])
             : 0;
}

double LoopCloser::HeadingWindowRad(const KeyFrameMap& map, std::size_t current, std::size_t j,
                                    const GraphReach& reach) const {
  return std::min(options_.max_wide_window_rad,
                  MatchedHeadingRad(map, current, j, reach) + OdometryHeadingRad(j, reach));
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

MapPoints LoopCloser::CandidateSubmap(const KeyFrameMap& map, std::size_t current,
                                      std::size_t candidate) const {
  const auto& frames = map.key_frames();
  // The submap stops short of the recent path, so the loop is checked against old map only.
  std::size_t last = std::min(candidate + options_.submap_half_window, current - 1);
  while (last > candidate && frames[current].path_length_m - frames[last].path_length_m <
                                 options_.min_path_separation_m) {
    --last;
  }
  const std::size_t first =
      candidate > options_.submap_half_window ? candidate - options_.submap_half_window : 0;
  return map.WorldPoints(first, last);
}

LoopAttempt LoopCloser::TryCandidate(const KeyFrameMap& map, std::size_t current,
                                     std::size_t candidate, double min_ratio,
                                     double heading_rad) const {
  const KeyFrame& now = map.key_frames()[current];
  MapPoints submap = CandidateSubmap(map, current, candidate);
  const IcpTarget target(std::move(submap.points), std::move(submap.normals));

  const Points2 source = SourcePoints(map, current);
  IcpResult match = MatchIcp(source, target, now.T_world_base, options_.icp);
  double heading_span_rad = options_.guess_step_rad;  // of the initial guesses, if tried
  if (!(match.converged && match.inlier_ratio >= min_ratio)) {
    // A small grid of initial guesses around the estimate (drift moved the old map), tried
    // with every third point; the best is refined with all of them. The headings step by
    // guess_step_rad over the heading window, at least one step either side.
    Points2 sparse;
    for (std::size_t i = 0; i < source.size(); i += 3) sparse.push_back(source[i]);
    const int headings =
        std::max(1, static_cast<int>(std::ceil(heading_rad / options_.guess_step_rad)));
    heading_span_rad = headings * options_.guess_step_rad;
    IcpResult best_sparse;
    for (int ix = -1; ix <= 1; ++ix) {
      for (int iy = -1; iy <= 1; ++iy) {
        for (int it = -headings; it <= headings; ++it) {
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
  // The agreement check allows the guesses' span beyond the first step (Judge adds that one).
  return Judge(map, current, candidate, match, min_ratio,
               {0, 0, heading_span_rad - options_.guess_step_rad});
}

LoopAttempt LoopCloser::TryWide(const KeyFrameMap& map, std::size_t current,
                                const GraphReach& reach) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  // Every earlier key frame whose view can overlap the scan within the drift it can have; the
  // window covers the largest of those drifts.
  std::vector<std::size_t> reachable;
  double window_m = 0, window_rad = 0;
  for (std::size_t j = 0; j < current; ++j) {
    if (now.path_length_m - frames[j].path_length_m < options_.min_path_separation_m) break;
    const double graph_m = GraphDistance(frames, current, j, reach);
    const double drift_m = std::min(options_.max_wide_window_m,
                                    options_.wide_window_m + options_.wide_window_per_m * graph_m);
    const double distance = std::hypot(frames[j].T_world_base.x_m - now.T_world_base.x_m,
                                       frames[j].T_world_base.y_m - now.T_world_base.y_m);
    if (drift_m < options_.min_wide_window_m || distance > drift_m + options_.search_radius_m) {
      continue;
    }
    reachable.push_back(j);
    window_m = std::max(window_m, drift_m);
    window_rad = std::max(window_rad, HeadingWindowRad(map, current, j, reach));
  }
  if (reachable.empty()) return {};
  MapPoints submap = map.WorldPoints(reachable);
  const Points2 source = SourcePoints(map, current);
  const CorrelativeResult coarse = MatchCorrelative(source, submap.points, now.T_world_base,
                                                    window_m, window_rad, options_.correlative);
  LoopAttempt attempt;
  attempt.candidate = reachable.front();
  if (!coarse.found) {
    attempt.verdict = LoopVerdict::kRejectedMatch;
    return attempt;
  }
  const IcpTarget target(std::move(submap.points), std::move(submap.normals));
  const IcpResult match = MatchIcp(source, target, coarse.T_target_source, options_.icp);
  // The edge starts at the reachable key frame nearest to the matched pose.
  attempt = Judge(map, current, NearestOf(map, reachable, match.T_target_source), match,
                  options_.min_matching_ratio, {window_m, window_m, window_rad});
  if (attempt.verdict == LoopVerdict::kAccepted &&
      match.inlier_ratio < options_.min_wide_matching_ratio) {
    // Too weak alone; worth confirming only where the scans lost the heading (see
    // confirm_within_key_frames).
    const std::size_t j = attempt.candidate;
    attempt.verdict = OdometryHeadingRad(j, reach) > MatchedHeadingRad(map, current, j, reach)
                          ? LoopVerdict::kTentative
                          : LoopVerdict::kRejectedMatch;
  }
  return attempt;
}

LoopAttempt LoopCloser::Judge(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                              const IcpResult& match, double min_ratio,
                              const PlanarPose& window) const {
  const auto& frames = map.key_frames();
  const KeyFrame& now = frames[current];
  LoopAttempt attempt;
  attempt.candidate = candidate;
  attempt.match = match;
  attempt.window = window;
  if (!match.converged || match.inlier_ratio < min_ratio ||
      match.rms_residual_m > options_.max_rms_residual_m) {
    attempt.verdict = LoopVerdict::kRejectedMatch;
    return attempt;
  }
  attempt.weakest_sigma_m = WeakestSigmaM(match.information, options_.heading_lever_arm_m);
  if (*attempt.weakest_sigma_m > options_.max_weakest_sigma_m) {
    attempt.verdict = LoopVerdict::kRejectedDegenerate;
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

#include "reconstruct/pose_graph.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <string>
#include <utility>

#include <ceres/ceres.h>
#include <Eigen/LU>

#include "core/error.hpp"
#include "reconstruct/pose_problem.hpp"

namespace littermap::reconstruct {

void PoseGraphOptions::Validate() const {
  if (!(loop_loss_scale > 0) || !(landmark_loss_scale > 0)) {
    throw UsageError("pose graph: loop_loss_scale and landmark_loss_scale must be > 0");
  }
  if (max_iterations < 1) throw UsageError("pose graph: max_iterations must be >= 1");
}

PoseGraphResult OptimizePoseGraph(std::vector<PlanarPose>* poses,
                                  const std::vector<PoseGraphEdge>& edges,
                                  const PoseGraphOptions& options, LandmarkTerms* landmarks) {
  PoseGraphResult result;
  const bool with_landmarks = landmarks != nullptr && !landmarks->terms.empty();
  if (poses->size() < 2 || (edges.empty() && !with_landmarks)) {
    result.usable = true;
    return result;
  }
  std::vector<std::array<double, 3>> parameters(poses->size());
  for (std::size_t i = 0; i < poses->size(); ++i) {
    parameters[i] = {(*poses)[i].x_m, (*poses)[i].y_m, (*poses)[i].theta_rad};
  }
  ceres::Problem problem;
  for (const PoseGraphEdge& edge : edges) {
    if (edge.from >= poses->size() || edge.to >= poses->size()) {
      throw InternalError("pose graph: edge " + std::to_string(edge.from) + " -> " +
                          std::to_string(edge.to) + " names a missing pose");
    }
    ceres::LossFunction* loss = edge.loop ? new ceres::HuberLoss(options.loop_loss_scale) : nullptr;
    problem.AddResidualBlock(RelativePoseError::Create(edge.T_from_to, edge.information), loss,
                             parameters[edge.from].data(), parameters[edge.to].data());
  }
  std::vector<std::array<double, 2>> positions;
  if (with_landmarks) {
    positions.resize(landmarks->positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] = {landmarks->positions[i].x(), landmarks->positions[i].y()};
    }
    for (const LandmarkTerm& term : landmarks->terms) {
      if (term.pose >= poses->size() || term.landmark >= positions.size()) {
        throw InternalError("pose graph: a landmark term names a missing pose or landmark");
      }
      problem.AddResidualBlock(RangeBearingError::Create(term.centre_base, term.covariance_base),
                               new ceres::HuberLoss(options.landmark_loss_scale),
                               parameters[term.pose].data(), positions[term.landmark].data());
    }
  }
  if (problem.HasParameterBlock(parameters[0].data())) {
    problem.SetParameterBlockConstant(parameters[0].data());
  }
  const ceres::Solver::Summary summary = SolvePoseProblem(&problem, options.max_iterations);
  result.usable = summary.IsSolutionUsable();
  result.iterations = static_cast<int>(summary.iterations.size());
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  if (result.usable) {
    for (std::size_t i = 0; i < poses->size(); ++i) {
      (*poses)[i] = {parameters[i][0], parameters[i][1], WrapAngle(parameters[i][2])};
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
      landmarks->positions[i] = {positions[i][0], positions[i][1]};
    }
  }
  return result;
}

double LandmarkChi2(const PlanarPose& pose, const Eigen::Vector2d& position,
                    const LandmarkTerm& term) {
  const double a[3] = {pose.x_m, pose.y_m, pose.theta_rad};
  const double l[2] = {position.x(), position.y()};
  return RangeBearingError(term.centre_base, term.covariance_base).Chi2(a, l);
}

Eigen::Matrix3d DiagonalInformation(double sigma_m, double sigma_rad) {
  return Eigen::Vector3d(1 / (sigma_m * sigma_m), 1 / (sigma_m * sigma_m),
                         1 / (sigma_rad * sigma_rad))
      .asDiagonal();
}

Eigen::Matrix3d EdgeInformation(const Eigen::Matrix3d& information_world, double theta_from_rad,
                                double sigma_floor_m, double sigma_floor_rad) {
  // e_world = G e_local with G = diag(R(theta_from), 1), so Sigma_local = G^T Sigma_world G.
  const Eigen::Matrix3d symmetric = 0.5 * (information_world + information_world.transpose());
  const Eigen::Matrix3d covariance_world =
      (symmetric + 1e-9 * Eigen::Matrix3d::Identity()).inverse();
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  const double c = std::cos(theta_from_rad), s = std::sin(theta_from_rad);
  G.topLeftCorner<2, 2>() << c, -s, s, c;
  Eigen::Matrix3d covariance = G.transpose() * covariance_world * G;
  covariance += Eigen::Vector3d(sigma_floor_m * sigma_floor_m, sigma_floor_m * sigma_floor_m,
                                sigma_floor_rad * sigma_floor_rad)
                    .asDiagonal();
  return covariance.inverse();
}

std::vector<double> GraphDistances(std::size_t poses, const std::vector<PoseGraphEdge>& edges,
                                   std::size_t source) {
  return GraphDistances(poses, edges, source, [](const PoseGraphEdge& edge) {
    return std::hypot(edge.T_from_to.x_m, edge.T_from_to.y_m);
  });
}

std::vector<double> GraphDistances(std::size_t poses, const std::vector<PoseGraphEdge>& edges,
                                   std::size_t source,
                                   const std::function<double(const PoseGraphEdge&)>& length) {
  std::vector<std::vector<std::pair<std::size_t, double>>> adjacent(poses);
  for (const PoseGraphEdge& edge : edges) {
    if (edge.from >= poses || edge.to >= poses || edge.heading_only) continue;
    const double edge_length = length(edge);
    adjacent[edge.from].emplace_back(edge.to, edge_length);
    adjacent[edge.to].emplace_back(edge.from, edge_length);
  }
  std::vector<double> distance(poses, std::numeric_limits<double>::infinity());
  if (source >= poses) return distance;
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[source] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {  // Dijkstra
    const auto [d, node] = queue.top();
    queue.pop();
    if (d > distance[node]) continue;
    for (const auto& [next, step] : adjacent[node]) {
      if (d + step < distance[next]) {
        distance[next] = d + step;
        queue.emplace(distance[next], next);
      }
    }
  }
  return distance;
}

double EdgeChi2(const std::vector<PlanarPose>& poses, const PoseGraphEdge& edge) {
  const PlanarPose measured_error =
      Between(edge.T_from_to, Between(poses[edge.from], poses[edge.to]));
  // Same error as the residual to first order; exact for the translation in a's frame.
  const PlanarPose predicted = Between(poses[edge.from], poses[edge.to]);
  Eigen::Vector3d e(predicted.x_m - edge.T_from_to.x_m, predicted.y_m - edge.T_from_to.y_m,
                    measured_error.theta_rad);
  return e.dot(edge.information * e);
}

LoopPruning PruneLoops(std::vector<PlanarPose>* poses, std::vector<PoseGraphEdge>* edges,
                       double max_chi2, const PoseGraphOptions& options, LandmarkTerms* landmarks) {
  LoopPruning pruning;
  for (;;) {
    std::optional<std::size_t> worst;
    double worst_chi2 = max_chi2;
    for (std::size_t i = 0; i < edges->size(); ++i) {
      if (!(*edges)[i].loop) continue;
      const double chi2 = EdgeChi2(*poses, (*edges)[i]);
      if (chi2 > worst_chi2) {
        worst_chi2 = chi2;
        worst = i;
      }
    }
    if (!worst) return pruning;
    edges->erase(edges->begin() + static_cast<std::ptrdiff_t>(*worst));
    ++pruning.removed;
    std::vector<PlanarPose> optimised = *poses;
    std::optional<LandmarkTerms> moved;
    if (landmarks != nullptr) moved = *landmarks;
    const PoseGraphResult result =
        OptimizePoseGraph(&optimised, *edges, options, moved ? &*moved : nullptr);
    pruning.usable = result.usable;
    if (!result.usable) return pruning;
    pruning.final_cost = result.final_cost;
    *poses = std::move(optimised);
    if (moved) *landmarks = std::move(*moved);
  }
}

}  // namespace littermap::reconstruct

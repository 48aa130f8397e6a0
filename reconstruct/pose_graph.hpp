#pragma once
// Pose graph over key frames, optimised with Ceres: nodes are SE(2) poses T_world_keyframe,
// edges relative measurements T_from_to (scan matching between consecutive key frames, odometry
// where matching failed, loop closures) weighted by their information. The first pose is held
// constant (it fixes the gauge); loop edges get a robust (Huber) loss so that a wrong loop that
// slipped through the checks pulls with a bounded force rather than quadratically; Huber, unlike
// Cauchy, stays convex, so a true loop far from the drifted estimate is still pulled in.

#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/planar_pose.hpp"

namespace littermap::reconstruct {

struct PoseGraphEdge {
  std::size_t from = 0;
  std::size_t to = 0;
  PlanarPose T_from_to;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();  // order (x, y, theta)
  bool loop = false;
  bool camera = false;  // a loop from an RGB-D alignment (else from scan matching)
  // An edge to a key frame placed by odometry alone: the standard deviation of its heading by the
  // odometry model (zero for a matched edge, whose drift the matcher bounds per metre).
  double odometry_sigma_rad = 0;
  bool heading_only = false;  // a gyro's turn between two key frames: no path between them
};

// The tracker's step from a key frame to the next: not a loop, not a gyro's turn alone.
inline bool IsTrackerStep(const PoseGraphEdge& edge) {
  return !edge.loop && !edge.heading_only && edge.to == edge.from + 1;
}

// Landmarks in the graph: 2D points, each sighting a range-bearing factor from its pose
// (RangeBearingError) with a robust loss, so a wrong association pulls with a bounded force.
struct LandmarkTerm {
  std::size_t pose = 0;
  std::size_t landmark = 0;  // index into LandmarkTerms::positions
  Eigen::Vector2d centre_base = Eigen::Vector2d::Zero();
  Eigen::Matrix2d covariance_base = Eigen::Matrix2d::Identity();
};

struct LandmarkTerms {
  std::vector<Eigen::Vector2d> positions;  // world frame, optimised in place
  std::vector<LandmarkTerm> terms;
};

struct PoseGraphOptions {
  double loop_loss_scale = 3.0;      // Huber scale on the whitened loop residual
  double landmark_loss_scale = 2.0;  // Huber scale on the whitened landmark residual
  int max_iterations = 50;
  void Validate() const;
};

struct PoseGraphResult {
  bool usable = false;  // Ceres returned a usable solution
  int iterations = 0;
  double initial_cost = 0;
  double final_cost = 0;
};

// Optimises poses (and the landmarks' positions, if given) in place.
PoseGraphResult OptimizePoseGraph(std::vector<PlanarPose>* poses,
                                  const std::vector<PoseGraphEdge>& edges,
                                  const PoseGraphOptions& options,
                                  LandmarkTerms* landmarks = nullptr);

// Chi-squared (2 degrees of freedom) of one landmark sighting at the given values.
double LandmarkChi2(const PlanarPose& pose, const Eigen::Vector2d& position,
                    const LandmarkTerm& term);

// Information of independent errors with these standard deviations in x and y and in theta.
Eigen::Matrix3d DiagonalInformation(double sigma_m, double sigma_rad);

// The information of an edge from a into b, given the information of b's pose in the world
// frame as a matcher estimated it (order x, y, theta): rotated into a's frame, where the edge's
// translation residual lives, and with a floor added to the covariance. The floor stands for
// what the Gauss-Newton Hessian does not see (correlated points, the map's own error), which
// otherwise makes every edge millimetre-sure and a true loop look like an outlier.
Eigen::Matrix3d EdgeInformation(const Eigen::Matrix3d& information_world, double theta_from_rad,
                                double sigma_floor_m, double sigma_floor_rad);

// Distance of every pose from `source` along the graph's edges (shortest path, each edge as long
// as its translation, or as `length` says); infinity for poses it does not reach.
std::vector<double> GraphDistances(std::size_t poses, const std::vector<PoseGraphEdge>& edges,
                                   std::size_t source);
std::vector<double> GraphDistances(std::size_t poses, const std::vector<PoseGraphEdge>& edges,
                                   std::size_t source,
                                   const std::function<double(const PoseGraphEdge&)>& length);

// r^T I r of one edge at the given poses (chi-squared with 3 degrees of freedom if the
// information is right).
double EdgeChi2(const std::vector<PlanarPose>& poses, const PoseGraphEdge& edge);

struct LoopPruning {
  std::size_t removed = 0;
  bool usable = true;  // the last optimisation returned a usable solution
  double final_cost = 0;
};

// Removes the loop edges an optimised graph cannot satisfy, worst first: while the loop edge
// with the largest chi-squared (EdgeChi2) exceeds max_chi2, it is taken out and the graph
// optimised again. Wrong loops that agree with each other can each pass a check made when they
// were added, and the graph then bends to fit them; once the loops found later pull the other
// way, the wrong ones stand out. Poses are updated only while the solutions are usable.
LoopPruning PruneLoops(std::vector<PlanarPose>* poses, std::vector<PoseGraphEdge>* edges,
                       double max_chi2, const PoseGraphOptions& options,
                       LandmarkTerms* landmarks = nullptr);

}  // namespace littermap::reconstruct

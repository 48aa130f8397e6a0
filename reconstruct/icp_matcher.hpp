#pragma once
// 2D ICP scan matcher (thesis 2.3, Alg. 2.3.1): for each source point the closest target point
// (KD-tree), pairs farther apart than the current distance threshold dropped, the rigid SE(2)
// transform minimising the squared error estimated by Gauss-Newton, repeated until converged.
// The threshold follows a coarse-to-fine schedule: a large threshold first tolerates a poor
// initial guess, a small one last keeps wrong pairs from pulling (thesis 2.3 on dist_threshold).
// Point-to-line residuals (Censi, ICRA 2008) are the default: they slide along walls instead of
// snapping to the sampling of the target.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct IcpOptions {
  std::vector<double> max_correspondence_distances_m = {0.6, 0.3, 0.15, 0.08};
  int max_iterations_per_stage = 15;
  double convergence_translation_m = 5e-4;
  double convergence_rotation_rad = 5e-4;
  bool point_to_line = true;
  int normal_neighbours = 5;
  // A source point is an inlier (counts for the matching ratio) within this distance of the
  // target after convergence.
  double inlier_distance_m = 0.1;
  std::size_t min_correspondences = 15;
  // Floor of the residual standard deviation used for the information estimate.
  double min_residual_sigma_m = 0.01;
  void Validate() const;
};

struct IcpResult {
  PlanarPose T_target_source;
  bool converged = false;
  int iterations = 0;
  std::size_t correspondences = 0;  // in the last iteration
  double inlier_ratio = 0;          // the thesis's matching ratio, in [0, 1]
  double rms_residual_m = 0;
  // Gauss-Newton Hessian J^T J / sigma^2 at the solution, order (x, y, theta): the information
  // of the estimate (its inverse approximates the covariance).
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
};

// Target points with a KD-tree (nanoflann) and, for point-to-line, a normal per point from the
// principal axes of its neighbourhood.
class IcpTarget {
 public:
  IcpTarget(Points2 points, const IcpOptions& options);
  // With normals computed before (EstimateNormals), e.g. once per key frame.
  IcpTarget(Points2 points, Points2 normals);
  ~IcpTarget();
  IcpTarget(const IcpTarget&) = delete;
  IcpTarget& operator=(const IcpTarget&) = delete;

  const Points2& points() const { return points_; }
  // Unit normal, or zero when the neighbourhood is not line-like (point-to-point is used there).
  const Eigen::Vector2d& normal(std::size_t i) const { return normals_[i]; }
  bool has_normals() const { return !normals_.empty(); }
  // Closest target point no farther than sqrt(max_distance_sq) from the query; false if there
  // is none. The bound also bounds the search: matching is fast however far the scan is off.
  bool NearestWithin(const Eigen::Vector2d& query, double max_distance_sq, std::size_t* index,
                     double* distance_sq) const;

 private:
  struct Index;
  Points2 points_;
  Points2 normals_;
  std::unique_ptr<Index> index_;
};

// Unit normal of the line through points[indices]: the eigenvector of the smaller eigenvalue of
// their scatter matrix, or zero when the spread across is more than a tenth of the spread along
// (not a line) or there are fewer than 3 points.
Eigen::Vector2d LineNormal(const Points2& points, std::span<const std::uint32_t> indices);

// Line normals of points (zero where not line-like), from each point's neighbourhood.
Points2 EstimateNormals(const Points2& points, const IcpOptions& options);

IcpResult MatchIcp(const Points2& source, const IcpTarget& target, const PlanarPose& initial,
                   const IcpOptions& options);

}  // namespace littermap::reconstruct

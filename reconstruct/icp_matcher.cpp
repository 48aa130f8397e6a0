#include "reconstruct/icp_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>
#include <nanoflann.hpp>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

struct PointsAdaptor {
  const Points2* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][int(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>,
                                        PointsAdaptor, 2, std::uint32_t>;

struct Accumulated {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  double squared_error = 0;
  std::size_t count = 0;
};

// Gauss-Newton normal equations at pose T for the pairs within max_distance.
// Point-to-line: r = n . (R p + t - q), J = [n_x, n_y, n . (R' p)] with R' p = perp(R p).
Accumulated Accumulate(const Points2& source, const IcpTarget& target, const PlanarPose& T,
                       double max_distance, bool point_to_line) {
  Accumulated acc;
  const double max_sq = max_distance * max_distance;
  const double c = std::cos(T.theta_rad), s = std::sin(T.theta_rad);
  for (const Eigen::Vector2d& p : source) {
    const Eigen::Vector2d rp(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    const Eigen::Vector2d moved(rp.x() + T.x_m, rp.y() + T.y_m);
    std::size_t index = 0;
    double distance_sq = 0;
    if (!target.NearestWithin(moved, max_sq, &index, &distance_sq)) continue;
    const Eigen::Vector2d error = moved - target.points()[index];
    const Eigen::Vector2d perp(-rp.y(), rp.x());
    const Eigen::Vector2d n =
        point_to_line && target.has_normals() ? target.normal(index) : Eigen::Vector2d::Zero();
    if (n.squaredNorm() > 0.5) {
      const Eigen::Vector3d J(n.x(), n.y(), n.dot(perp));
      const double r = n.dot(error);
      acc.H += J * J.transpose();
      acc.g += J * r;
      acc.squared_error += r * r;
    } else {
      Eigen::Matrix<double, 2, 3> J;
      J << 1, 0, perp.x(), 0, 1, perp.y();
      acc.H += J.transpose() * J;
      acc.g += J.transpose() * error;
      acc.squared_error += error.squaredNorm();
    }
    ++acc.count;
  }
  return acc;
}

}  // namespace

Eigen::Vector2d LineNormal(const Points2& points, std::span<const std::uint32_t> indices) {
  const std::size_t n = indices.size();
  if (n < 3) return Eigen::Vector2d::Zero();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < n; ++k) mean += points[indices[k]];
  mean /= static_cast<double>(n);
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d d = points[indices[k]] - mean;
    scatter += d * d.transpose();
  }
  const double a = scatter(0, 0), b = scatter(0, 1), c = scatter(1, 1);
  const double half_trace = (a + c) / 2;
  const double root = std::sqrt(std::max(0.0, (a - c) * (a - c) / 4 + b * b));
  const double large = half_trace + root, small = half_trace - root;
  if (large <= 0 || small > 0.1 * large) return Eigen::Vector2d::Zero();
  // Eigenvector of the large eigenvalue is the line direction; the normal is perpendicular.
  Eigen::Vector2d direction = std::abs(b) > 1e-12
                                  ? Eigen::Vector2d(large - c, b)
                                  : (a >= c ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1));
  direction.normalize();
  return {-direction.y(), direction.x()};
}

// knnSearch restricted to the points no farther than sqrt(bound_sq): nanoflann's k-nearest
// result set with its worst distance preset to the bound, so the search never visits a subtree
// beyond it (plain knnSearch visits them until it has found k points, however far). The preset is
// a hair above the bound, since the search prunes on a lower bound of the distance summed up in
// another order; the points beyond the bound itself are then dropped. Same neighbours, in the same
// order, as knnSearch's within the bound. Returns how many it found.
std::size_t KnnWithin(const KdTree& tree, const double* query, std::size_t k, double bound_sq,
                      std::uint32_t* indices, double* distances_sq) {
  nanoflann::KNNResultSet<double, std::uint32_t> result(k);
  result.init(indices, distances_sq);
  distances_sq[k - 1] = bound_sq * (1 + 1e-9) + std::numeric_limits<double>::min();
  tree.findNeighbors(result, query, nanoflann::SearchParams());
  std::size_t within = result.size();
  while (within > 0 && distances_sq[within - 1] > bound_sq) --within;
  return within;
}

struct IcpTarget::Index {
  PointsAdaptor adaptor;
  KdTree tree;
  explicit Index(const Points2* points)
      : adaptor{points}, tree(2, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

void IcpOptions::Validate() const {
  if (max_correspondence_distances_m.empty()) {
    throw UsageError("icp: max_correspondence_distances_m must not be empty");
  }
  for (double d : max_correspondence_distances_m) {
    if (!(d > 0)) throw UsageError("icp: correspondence distances must be > 0");
  }
  if (max_iterations_per_stage < 1) throw UsageError("icp: max_iterations_per_stage must be >= 1");
  if (!(inlier_distance_m > 0)) throw UsageError("icp: inlier_distance_m must be > 0");
  if (normal_neighbours < 3) throw UsageError("icp: normal_neighbours must be >= 3");
}

IcpTarget::IcpTarget(Points2 points, const IcpOptions& options) : points_(std::move(points)) {
  index_ = std::make_unique<Index>(&points_);
  if (!options.point_to_line || points_.empty()) return;
  const auto k = static_cast<std::size_t>(options.normal_neighbours);
  std::vector<std::uint32_t> indices(k);
  std::vector<double> distances(k);
  normals_.resize(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    // Neighbours 0.5 m away or farther belong to another surface.
    const std::size_t near = KnnWithin(index_->tree, points_[i].data(), k,
                                       std::nextafter(0.25, 0.0), indices.data(), distances.data());
    normals_[i] = LineNormal(points_, std::span(indices.data(), near));
  }
}

IcpTarget::IcpTarget(Points2 points, Points2 normals)
    : points_(std::move(points)), normals_(std::move(normals)) {
  if (!normals_.empty() && normals_.size() != points_.size()) {
    throw InternalError("icp target: " + std::to_string(normals_.size()) + " normals for " +
                        std::to_string(points_.size()) + " points");
  }
  index_ = std::make_unique<Index>(&points_);
}

Points2 EstimateNormals(const Points2& points, const IcpOptions& options) {
  const IcpTarget target(points, options);
  Points2 normals;
  if (!target.has_normals()) return normals;
  normals.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) normals.push_back(target.normal(i));
  return normals;
}

IcpTarget::~IcpTarget() = default;

bool IcpTarget::NearestWithin(const Eigen::Vector2d& query, double max_distance_sq,
                              std::size_t* index, double* distance_sq) const {
  if (points_.empty()) return false;
  std::uint32_t found = 0;
  if (KnnWithin(index_->tree, query.data(), 1, max_distance_sq, &found, distance_sq) == 0) {
    return false;
  }
  *index = found;
  return true;
}

IcpResult MatchIcp(const Points2& source, const IcpTarget& target, const PlanarPose& initial,
                   const IcpOptions& options) {
  IcpResult result;
  result.T_target_source = initial;
  if (source.empty() || target.points().empty()) return result;
  PlanarPose T = initial;
  bool last_stage_converged = false;
  for (std::size_t stage = 0; stage < options.max_correspondence_distances_m.size(); ++stage) {
    const double max_distance = options.max_correspondence_distances_m[stage];
    last_stage_converged = false;
    for (int iteration = 0; iteration < options.max_iterations_per_stage; ++iteration) {
      ++result.iterations;
      const Accumulated acc = Accumulate(source, target, T, max_distance, options.point_to_line);
      result.correspondences = acc.count;
      if (acc.count < options.min_correspondences) return result;  // not converged
      // A little damping keeps the step finite along a corridor, where point-to-line leaves
      // the motion along the walls unconstrained.
      const Eigen::Matrix3d H =
          acc.H + 1e-6 * static_cast<double>(acc.count) * Eigen::Matrix3d::Identity();
      const Eigen::Vector3d delta = H.ldlt().solve(-acc.g);
      // The Jacobian above is for R <- R(dtheta) R, t <- t + dt.
      T = {T.x_m + delta.x(), T.y_m + delta.y(), WrapAngle(T.theta_rad + delta.z())};
      if (delta.head<2>().norm() < options.convergence_translation_m &&
          std::abs(delta.z()) < options.convergence_rotation_rad) {
        last_stage_converged = true;
        break;
      }
    }
  }
  result.T_target_source = T;
  const Accumulated final_acc =
      Accumulate(source, target, T, options.inlier_distance_m, options.point_to_line);
  result.correspondences = final_acc.count;
  result.inlier_ratio = static_cast<double>(final_acc.count) / static_cast<double>(source.size());
  if (final_acc.count > 3) {
    result.rms_residual_m =
        std::sqrt(final_acc.squared_error / static_cast<double>(final_acc.count));
    const double sigma =
        std::max(options.min_residual_sigma_m,
                 std::sqrt(final_acc.squared_error / static_cast<double>(final_acc.count - 3)));
    result.information = final_acc.H / (sigma * sigma);
  }
  result.converged = last_stage_converged && final_acc.count >= options.min_correspondences;
  return result;
}

}  // namespace littermap::reconstruct

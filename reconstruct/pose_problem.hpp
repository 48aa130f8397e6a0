#pragma once
// The Ceres pieces of a least-squares problem over planar poses (x, y, theta), shared by the pose
// graph and the final scan alignment: the residual of a relative pose measurement, and the
// solver as both run it.

#include <cmath>
#include <numbers>

#include <ceres/ceres.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "core/planar_pose.hpp"

namespace littermap::reconstruct {

// Into [-pi, pi), differentiable almost everywhere (as ceres/examples/slam/pose_graph_2d).
template <typename T>
T NormalizeAngle(const T& angle) {
  const T two_pi(2.0 * std::numbers::pi);
  return angle - two_pi * ceres::floor((angle + T(std::numbers::pi)) / two_pi);
}

// A relative SE(2) pose measurement T_ab between poses a and b, whitened by its information:
//   r = S * [ R(theta_a)^T (t_b - t_a) - t_ab ;  normalize(theta_b - theta_a - theta_ab) ]
// with S the upper Cholesky factor of the information (S^T S = I), so ||r||^2 = e^T I e.
class RelativePoseError {
 public:
  RelativePoseError(const PlanarPose& T_ab, const Eigen::Matrix3d& sqrt_information)
      : T_ab_(T_ab), sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* const a, const T* const b, T* residual) const {
    const T c = ceres::cos(a[2]), s = ceres::sin(a[2]);
    const T dx = b[0] - a[0], dy = b[1] - a[1];
    Eigen::Matrix<T, 3, 1> e;
    e(0) = c * dx + s * dy - T(T_ab_.x_m);
    e(1) = -s * dx + c * dy - T(T_ab_.y_m);
    e(2) = NormalizeAngle(b[2] - a[2] - T(T_ab_.theta_rad));
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = sqrt_information_.cast<T>() * e;
    return true;
  }

  static ceres::CostFunction* Create(const PlanarPose& T_ab, const Eigen::Matrix3d& information) {
    return new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
        new RelativePoseError(T_ab, SqrtInformation(information)));
  }

  static Eigen::Matrix3d SqrtInformation(const Eigen::Matrix3d& information) {
    // A tiny ridge keeps a rank-deficient estimate (a corridor) positive definite.
    const Eigen::Matrix3d symmetric =
        0.5 * (information + information.transpose()) + 1e-9 * Eigen::Matrix3d::Identity();
    return symmetric.llt().matrixU();
  }

 private:
  PlanarPose T_ab_;
  Eigen::Matrix3d sqrt_information_;
};

// A landmark seen from pose a: its centre in a's frame as range and bearing from a's origin,
//   r = S * [ |p| - range ;  normalize(atan2(p_y, p_x) - bearing) ],  p = R(theta_a)^T (l - t_a)
// whitened by the square root of the measurement's information in range and bearing, which the
// constructor takes from the centre's covariance in a's frame (Sigma_rb = J Sigma_xy J^T with J
// the Jacobian of range and bearing at the measured centre).
class RangeBearingError {
 public:
  RangeBearingError(const Eigen::Vector2d& centre_a, const Eigen::Matrix2d& covariance_a) {
    range_ = centre_a.norm();
    bearing_ = std::atan2(centre_a.y(), centre_a.x());
    const double r2 = range_ * range_;
    Eigen::Matrix2d J;
    J << centre_a.x() / range_, centre_a.y() / range_, -centre_a.y() / r2, centre_a.x() / r2;
    const Eigen::Matrix2d covariance = J * covariance_a * J.transpose();
    const Eigen::Matrix2d information = (0.5 * (covariance + covariance.transpose())).inverse() +
                                        1e-9 * Eigen::Matrix2d::Identity();
    sqrt_information_ = information.llt().matrixU();
  }

  template <typename T>
  bool operator()(const T* const a, const T* const landmark, T* residual) const {
    const T c = ceres::cos(a[2]), s = ceres::sin(a[2]);
    const T dx = landmark[0] - a[0], dy = landmark[1] - a[1];
    const T x = c * dx + s * dy, y = -s * dx + c * dy;
    Eigen::Matrix<T, 2, 1> e;
    e(0) = ceres::sqrt(x * x + y * y) - T(range_);
    e(1) = NormalizeAngle(ceres::atan2(y, x) - T(bearing_));
    Eigen::Map<Eigen::Matrix<T, 2, 1>> r(residual);
    r = sqrt_information_.cast<T>() * e;
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector2d& centre_a,
                                     const Eigen::Matrix2d& covariance_a) {
    return new ceres::AutoDiffCostFunction<RangeBearingError, 2, 3, 2>(
        new RangeBearingError(centre_a, covariance_a));
  }

  // The squared whitened residual at these values (chi-squared, 2 degrees of freedom).
  double Chi2(const double* a, const double* landmark) const {
    double residual[2];
    (*this)(a, landmark, residual);
    return residual[0] * residual[0] + residual[1] * residual[1];
  }

 private:
  double range_ = 0;
  double bearing_ = 0;
  Eigen::Matrix2d sqrt_information_;
};

// Solves on one thread with sparse normal Cholesky, silently (libraries do not print).
inline ceres::Solver::Summary SolvePoseProblem(ceres::Problem* problem, int max_iterations) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem, &summary);
  return summary;
}

}  // namespace littermap::reconstruct

#include "reconstruct/landmark_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "core/error.hpp"

namespace littermap::reconstruct {

void LandmarkExtractionOptions::Validate() const {
  if (min_points < 3) throw UsageError("landmarks: min_points must be >= 3");
  if (!(min_radius_m > 0) || !(max_radius_m > min_radius_m)) {
    throw UsageError("landmarks: radii must satisfy 0 < min_radius_m < max_radius_m");
  }
  if (!(max_rms_residual_m > 0) || !(min_sagitta_rms >= 0) || !(max_range_m > 0) ||
      !(segment_gap_m > 0) || !(segment_gap_beams > 0) || !(range_sigma_m > 0) ||
      !(centre_sigma_floor_m >= 0)) {
    throw UsageError(
        "landmarks: residual, range and gap limits and range_sigma_m must be > 0, "
        "min_sagitta_rms and centre_sigma_floor_m >= 0");
  }
}

CircleFit FitCircle(const Points2& points) {
  CircleFit fit;
  const std::size_t n = points.size();
  if (n < 3) return fit;
  // Centred coordinates keep the normal equations well conditioned far from the origin.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(n);
  // Kasa: x^2 + y^2 + D x + E y + F = 0, linear in (D, E, F).
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = p - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1);
    A += row * row.transpose();
    b -= row * q.squaredNorm();
  }
  Eigen::FullPivLU<Eigen::Matrix3d> lu(A);
  if (lu.rank() < 3) return fit;
  const Eigen::Vector3d def = lu.solve(b);
  Eigen::Vector2d centre(-def(0) / 2, -def(1) / 2);
  double radius_sq = centre.squaredNorm() - def(2);
  if (!(radius_sq > 0) || !std::isfinite(radius_sq)) return fit;
  double radius = std::sqrt(radius_sq);
  // Gauss-Newton on d_i = |q_i - c| - r; J_i = [-(q_i - c)^T / |q_i - c|, -1].
  Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
  double sum_sq = 0;
  for (int iteration = 0; iteration < 10; ++iteration) {
    JtJ.setZero();
    Eigen::Vector3d Jtr = Eigen::Vector3d::Zero();
    sum_sq = 0;
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d d = p - mean - centre;
      const double distance = d.norm();
      if (distance < 1e-12) return fit;
      const double residual = distance - radius;
      const Eigen::Vector3d J(-d.x() / distance, -d.y() / distance, -1);
      JtJ += J * J.transpose();
      Jtr += J * residual;
      sum_sq += residual * residual;
    }
    const Eigen::Vector3d step = JtJ.ldlt().solve(-Jtr);
    if (!step.allFinite()) return fit;
    centre += step.head<2>();
    radius += step(2);
    if (step.norm() < 1e-9) break;
  }
  if (!(radius > 0) || !centre.allFinite()) return fit;
  sum_sq = 0;
  for (const Eigen::Vector2d& p : points) {
    const double residual = (p - mean - centre).norm() - radius;
    sum_sq += residual * residual;
  }
  fit.centre = centre + mean;
  fit.radius_m = radius;
  fit.rms_residual_m = std::sqrt(sum_sq / static_cast<double>(n));
  fit.normal_matrix = JtJ;
  fit.ok = true;
  return fit;
}

namespace {

// The circle of one segment, if it is a landmark's.
std::optional<LandmarkObservation> SegmentLandmark(const Points2& segment,
                                                   const Eigen::Vector2d& laser_base,
                                                   const LandmarkExtractionOptions& options) {
  const CircleFit fit = FitCircle(segment);
  if (!fit.ok || fit.radius_m < options.min_radius_m || fit.radius_m > options.max_radius_m ||
      fit.rms_residual_m > options.max_rms_residual_m) {
    return std::nullopt;
  }
  // Sagitta of the chord between the end echoes: a straight piece has none.
  const double half_chord = 0.5 * (segment.back() - segment.front()).norm();
  const double sagitta =
      fit.radius_m -
      std::sqrt(std::max(0.0, fit.radius_m * fit.radius_m - half_chord * half_chord));
  if (sagitta < options.min_sagitta_rms * std::max(fit.rms_residual_m, options.range_sigma_m)) {
    return std::nullopt;
  }
  // Convex toward the laser: the centre is further away than the echoes.
  double mean_range = 0;
  for (const Eigen::Vector2d& p : segment) mean_range += (p - laser_base).norm();
  mean_range /= static_cast<double>(segment.size());
  if ((fit.centre - laser_base).norm() <= mean_range) return std::nullopt;
  // A circle about the robot itself (hostile or broken ranges) has no bearing to be seen at.
  if (fit.centre.norm() <= fit.radius_m) return std::nullopt;

  const double sigma = std::max(fit.rms_residual_m, options.range_sigma_m);
  const Eigen::Matrix3d covariance =
      (fit.normal_matrix + 1e-12 * Eigen::Matrix3d::Identity()).inverse() * sigma * sigma;
  LandmarkObservation observation;
  observation.centre_base = fit.centre;
  observation.radius_m = fit.radius_m;
  observation.covariance_base =
      covariance.topLeftCorner<2, 2>() +
      options.centre_sigma_floor_m * options.centre_sigma_floor_m * Eigen::Matrix2d::Identity();
  observation.rms_residual_m = fit.rms_residual_m;
  observation.points = segment.size();
  if (!observation.covariance_base.allFinite()) return std::nullopt;
  return observation;
}

}  // namespace

std::vector<LandmarkObservation> ExtractLandmarks(const Points2& points_base,
                                                  const Eigen::Vector2d& laser_base,
                                                  double angle_increment_rad,
                                                  const LandmarkExtractionOptions& options) {
  std::vector<LandmarkObservation> landmarks;
  Points2 segment;
  const auto close_segment = [&] {
    if (segment.size() >= options.min_points) {
      if (auto landmark = SegmentLandmark(segment, laser_base, options)) {
        landmarks.push_back(*landmark);
      }
    }
    segment.clear();
  };
  const double spacing_rad = std::abs(angle_increment_rad);
  for (const Eigen::Vector2d& p : points_base) {
    const double range = (p - laser_base).norm();
    if (range > options.max_range_m) {
      close_segment();
      continue;
    }
    if (!segment.empty()) {
      const double gap =
          std::max(options.segment_gap_m, options.segment_gap_beams * spacing_rad * range);
      if ((p - segment.back()).norm() > gap) close_segment();
    }
    segment.push_back(p);
  }
  close_segment();
  return landmarks;
}

}  // namespace littermap::reconstruct

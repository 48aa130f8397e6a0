#include "detect/ground_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/error.hpp"
#include "detect/every_nth.hpp"

namespace littermap::detect {
namespace {

struct ComponentStats {
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  double z_sum = 0;
  int points = 0;
};

std::vector<ComponentStats> Stats(const OrganizedCloud& cloud, const Components& components) {
  std::vector<ComponentStats> stats(components.sizes.size());
  for (std::size_t i = 0; i < components.labels.size(); ++i) {
    const int label = components.labels[i];
    if (label < 0) continue;
    ComponentStats& s = stats[static_cast<std::size_t>(label)];
    s.normal_sum += cloud.normals[i].cast<double>();
    s.z_sum += cloud.points_m[i].z();
    ++s.points;
  }
  return stats;
}

Eigen::Matrix<double, 6, 1> Basis(double x, double y) {
  Eigen::Matrix<double, 6, 1> b;
  b << 1, x, y, x * x, x * y, y * y;
  return b;
}

// Least squares with two Huber reweighting passes (scale 2 cm): one stone or a few litter
// points in the ground component must not bend the surface.
GroundSurface FitSurface(const std::vector<Eigen::Vector3f>& points) {
  std::vector<double> weights(points.size(), 1.0);
  GroundSurface surface;
  for (int pass = 0; pass < 3; ++pass) {
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto basis = Basis(points[i].x(), points[i].y());
      A.noalias() += weights[i] * basis * basis.transpose();
      b.noalias() += weights[i] * points[i].z() * basis;
    }
    // A little ridge on the curvature terms: a narrow strip of ground cannot pin them down.
    for (int k = 3; k < 6; ++k) A(k, k) += 1e-2 * static_cast<double>(points.size());
    surface = GroundSurface(A.ldlt().solve(b));
    constexpr double kHuber = 0.02;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double r = std::abs(surface.HeightAbove(points[i]));
      weights[i] = r <= kHuber ? 1.0 : kHuber / r;
    }
  }
  return surface;
}

std::vector<Eigen::Vector3f> Sample(const OrganizedCloud& cloud,
                                    const std::vector<unsigned char>& mask, std::size_t count,
                                    std::size_t max_points) {
  std::vector<Eigen::Vector3f> points;
  EveryNth thinned(count / max_points);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (mask[i] && thinned.Take()) points.push_back(cloud.points_m[i]);
  }
  return points;
}

}  // namespace

void GroundOptions::Validate() const {
  constexpr const char* kStage = "segmentation";
  RequireOption(max_tilt_deg > 0 && max_tilt_deg < 90, kStage, "ground_max_tilt_deg",
                "between 0 and 90");
  RequireOption(max_level_offset_m > 0, kStage, "ground_max_level_offset_m", "> 0");
  RequireOption(min_component_points >= 10, kStage, "ground_min_component_points", ">= 10");
  RequireOption(min_joined_points >= 10, kStage, "ground_min_joined_points", ">= 10");
  RequireOption(max_join_residual_m > 0, kStage, "ground_max_join_residual_m", "> 0");
  RequireOption(max_fit_points >= 10, kStage, "ground max_fit_points", ">= 10");
  RequireOption(inlier_band_m > 0, kStage, "ground_inlier_band_m", "> 0");
  RequireOption(depth_noise_per_m2 >= 0, kStage, "depth_noise_per_m2", ">= 0");
}

GroundResult FindGround(const OrganizedCloud& cloud, const Components& components,
                        const GroundOptions& options) {
  const std::vector<ComponentStats> stats = Stats(cloud, components);
  const double min_cos = std::cos(options.max_tilt_deg * std::numbers::pi / 180.0);
  auto ground_like = [&](const ComponentStats& s) {
    const Eigen::Vector3d normal = s.normal_sum.normalized();
    return normal.z() >= min_cos && std::abs(s.z_sum / s.points) <= options.max_level_offset_m;
  };
  int seed = -1;
  for (std::size_t k = 0; k < stats.size(); ++k) {
    if (stats[k].points < options.min_component_points || !ground_like(stats[k])) continue;
    if (seed < 0 || stats[k].points > stats[static_cast<std::size_t>(seed)].points) {
      seed = static_cast<int>(k);
    }
  }
  GroundResult result;
  result.is_ground.assign(components.labels.size(), 0);
  if (seed < 0) return result;
  for (std::size_t i = 0; i < components.labels.size(); ++i) {
    result.is_ground[i] = components.labels[i] == seed;
  }
  result.points = static_cast<std::size_t>(stats[static_cast<std::size_t>(seed)].points);
  result.surface = FitSurface(Sample(cloud, result.is_ground, result.points,
                                     static_cast<std::size_t>(options.max_fit_points)));

  // Join the other ground-like components lying on the seed's surface.
  std::vector<std::vector<float>> residuals(stats.size());
  for (std::size_t i = 0; i < components.labels.size(); ++i) {
    const int label = components.labels[i];
    if (label < 0 || label == seed) continue;
    const ComponentStats& s = stats[static_cast<std::size_t>(label)];
    if (s.points < options.min_joined_points || !ground_like(s)) continue;
    residuals[static_cast<std::size_t>(label)].push_back(
        std::abs(static_cast<float>(result.surface.HeightAbove(cloud.points_m[i]))));
  }
  std::vector<unsigned char> joined(stats.size(), 0);
  for (std::size_t k = 0; k < stats.size(); ++k) {
    auto& r = residuals[k];
    if (r.empty()) continue;
    std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
    if (r[r.size() / 2] <= options.max_join_residual_m) {
      joined[k] = 1;
      ++result.components_joined;
    }
  }
  for (std::size_t i = 0; i < components.labels.size(); ++i) {
    const int label = components.labels[i];
    if (label >= 0 && joined[static_cast<std::size_t>(label)]) {
      result.is_ground[i] = 1;
      ++result.points;
    }
  }
  // Strict ground: keep the points on the surface, refit on them (twice).
  std::vector<Eigen::Vector3f> fit_points;
  for (int pass = 0; pass < 2; ++pass) {
    fit_points = Sample(cloud, result.is_ground, result.points,
                        static_cast<std::size_t>(options.max_fit_points));
    result.surface = FitSurface(fit_points);
    result.points = 0;
    for (std::size_t i = 0; i < result.is_ground.size(); ++i) {
      if (!result.is_ground[i]) continue;
      const float z = cloud.depth_m[i];
      const double band = options.inlier_band_m + 2 * options.depth_noise_per_m2 * z * z;
      if (std::abs(result.surface.HeightAbove(cloud.points_m[i])) > band) {
        result.is_ground[i] = 0;
      } else {
        ++result.points;
      }
    }
  }
  if (result.points < static_cast<std::size_t>(options.min_component_points)) {
    result.found = false;
    return result;
  }
  double squares = 0;
  for (const auto& p : fit_points) squares += std::pow(result.surface.HeightAbove(p), 2);
  result.rms_residual_m = std::sqrt(squares / static_cast<double>(fit_points.size()));
  result.found = true;
  return result;
}

}  // namespace littermap::detect

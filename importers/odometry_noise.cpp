#include "importers/odometry_noise.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace littermap::importers {
namespace {

// 53 random bits as a double in [0, 1): exact, and the same on every platform.
constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;

}  // namespace

double GaussianSampler::Next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // u1 in (0, 1] so that log(u1) is finite; u2 in [0, 1).
  const double u1 = static_cast<double>((engine_() >> 11) + 1) * kTwoToMinus53;
  const double u2 = static_cast<double>(engine_() >> 11) * kTwoToMinus53;
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

std::vector<PlanarPose> CorruptOdometry(std::span<const PlanarPose> reference, std::uint64_t seed,
                                        const OdometryNoiseOptions& options) {
  if (!(options.translation_sigma_per_m >= 0) || !(options.rotation_sigma_per_rad >= 0) ||
      !(options.rotation_sigma_per_m_rad >= 0) || !(options.rotation_sigma_floor_rad >= 0)) {
    throw UsageError("odometry noise sigmas must be non-negative");
  }
  std::vector<PlanarPose> odometry;
  odometry.reserve(reference.size());
  if (reference.empty()) return odometry;
  odometry.push_back(reference.front());
  GaussianSampler normal(seed);
  for (std::size_t i = 1; i < reference.size(); ++i) {
    const PlanarPose motion = Between(reference[i - 1], reference[i]);
    const double distance_m = std::hypot(motion.x_m, motion.y_m);
    const double sigma_xy = options.translation_sigma_per_m * distance_m;
    const double sigma_theta = options.rotation_sigma_per_rad * std::abs(motion.theta_rad) +
                               options.rotation_sigma_per_m_rad * distance_m +
                               options.rotation_sigma_floor_rad;
    PlanarPose noisy = motion;
    noisy.x_m += sigma_xy * normal.Next();
    noisy.y_m += sigma_xy * normal.Next();
    noisy.theta_rad += sigma_theta * normal.Next();
    odometry.push_back(Compose(odometry.back(), noisy));
  }
  return odometry;
}

}  // namespace littermap::importers

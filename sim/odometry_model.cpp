#include "sim/odometry_model.hpp"

#include <cmath>
#include <numbers>

#include "sim/random.hpp"

namespace littermap::sim {

std::vector<PlanarPose> SimulateOdometry(const std::vector<PlanarPose>& truth,
                                         const OdometrySpec& spec, std::uint64_t seed,
                                         const std::vector<BumpSpec>& bumps) {
  std::vector<PlanarPose> odometry;
  if (truth.empty()) return odometry;
  constexpr double kDegToRad = std::numbers::pi / 180;
  Rng rng(seed, 501);
  odometry.reserve(truth.size());
  odometry.push_back(truth.front());
  for (std::size_t i = 1; i < truth.size(); ++i) {
    PlanarPose delta = Between(truth[i - 1], truth[i]);
    const double d = std::hypot(delta.x_m, delta.y_m);
    const double sqrt_d = std::sqrt(d);
    // Three draws per step, always, so the stream does not depend on the motion.
    const double nx = rng.Normal(), ny = rng.Normal(), nr = rng.Normal();
    delta.x_m =
        delta.x_m * (1 + spec.scale_error) + nx * spec.translation_noise_m_per_sqrt_m * sqrt_d;
    delta.y_m =
        delta.y_m * (1 + spec.scale_error) + ny * spec.translation_noise_m_per_sqrt_m * sqrt_d;
    delta.theta_rad +=
        (spec.yaw_drift_deg_per_m * d + nr * spec.rotation_noise_deg_per_sqrt_m * sqrt_d) *
        kDegToRad;
    const double mid_x = 0.5 * (truth[i - 1].x_m + truth[i].x_m);
    const double mid_y = 0.5 * (truth[i - 1].y_m + truth[i].y_m);
    for (const BumpSpec& bump : bumps) {
      if (std::hypot(mid_x - bump.x_m, mid_y - bump.y_m) < bump.radius_m) {
        delta.theta_rad += bump.slip_deg * kDegToRad * d / (2 * bump.radius_m);
      }
    }
    odometry.push_back(Compose(odometry.back(), delta));
  }
  return odometry;
}

}  // namespace littermap::sim

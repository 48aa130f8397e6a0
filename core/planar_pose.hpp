#pragma once
// A pose in the plane (x, y, heading), the way CARMEN logs and 2D odometry describe a robot.
// Composition follows SE(2): T_a_c = T_a_b * T_b_c.

#include <cmath>
#include <numbers>

namespace littermap {

struct PlanarPose {
  double x_m = 0;
  double y_m = 0;
  double theta_rad = 0;
  bool operator==(const PlanarPose&) const = default;
};

// Wraps an angle into (-pi, pi].
inline double WrapAngle(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2 * std::numbers::pi;
  return wrapped;
}

// T_a_c = T_a_b * T_b_c.
inline PlanarPose Compose(const PlanarPose& T_a_b, const PlanarPose& T_b_c) {
  const double c = std::cos(T_a_b.theta_rad);
  const double s = std::sin(T_a_b.theta_rad);
  return {T_a_b.x_m + c * T_b_c.x_m - s * T_b_c.y_m, T_a_b.y_m + s * T_b_c.x_m + c * T_b_c.y_m,
          WrapAngle(T_a_b.theta_rad + T_b_c.theta_rad)};
}

// T_b_a from T_a_b.
inline PlanarPose Inverse(const PlanarPose& T_a_b) {
  const double c = std::cos(T_a_b.theta_rad);
  const double s = std::sin(T_a_b.theta_rad);
  return {-c * T_a_b.x_m - s * T_a_b.y_m, s * T_a_b.x_m - c * T_a_b.y_m,
          WrapAngle(-T_a_b.theta_rad)};
}

// T_a_b = inverse(T_w_a) * T_w_b: where b is, seen from a.
inline PlanarPose Between(const PlanarPose& T_w_a, const PlanarPose& T_w_b) {
  return Compose(Inverse(T_w_a), T_w_b);
}

}  // namespace littermap

#include "sim/route.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace littermap::sim {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180;

// The x interval where the horizontal line at y crosses the polygon (convex), or false.
bool LaneInterval(const std::vector<Eigen::Vector2d>& polygon, double y, double& x_min,
                  double& x_max) {
  x_min = std::numeric_limits<double>::infinity();
  x_max = -x_min;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if ((a.y() - y) * (b.y() - y) > 0 || a.y() == b.y()) continue;
    const double x = a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
  }
  return x_max - x_min > 1.0;
}

double Clamp(double value, double limit) { return std::clamp(value, -limit, limit); }

std::vector<Eigen::Vector2d> LawnmowerLanes(const RouteSpec& spec) {
  double y_min = std::numeric_limits<double>::infinity(), y_max = -y_min;
  for (const Eigen::Vector2d& p : spec.polygon_m) {
    y_min = std::min(y_min, p.y());
    y_max = std::max(y_max, p.y());
  }
  std::vector<Eigen::Vector2d> route;
  bool forward = true;
  for (double y = y_min + 0.5 * spec.lane_spacing_m; y < y_max; y += spec.lane_spacing_m) {
    double x_min = 0, x_max = 0;
    if (!LaneInterval(spec.polygon_m, y, x_min, x_max)) continue;
    const Eigen::Vector2d left(x_min + 0.5, y), right(x_max - 0.5, y);
    route.push_back(forward ? left : right);
    route.push_back(forward ? right : left);
    forward = !forward;
  }
  return route;
}

}  // namespace

std::vector<Eigen::Vector2d> PlanRoute(const RouteSpec& spec) {
  std::vector<Eigen::Vector2d> route =
      spec.type == "lawnmower" ? LawnmowerLanes(spec) : spec.waypoints_m;
  if (spec.come_home && route.size() >= 2 && (route.back() - route.front()).norm() > 1e-9) {
    route.push_back(route.front());
  }
  return route;
}

DriveResult DriveRoute(const std::vector<Eigen::Vector2d>& route, const DriveOptions& options) {
  DriveResult result;
  if (route.size() < 2) return result;
  const double dt = 1.0 / options.rate_hz;
  const Eigen::Vector2d first_leg = route[1] - route[0];
  RobotState state;
  const double start_heading_rad = std::atan2(first_leg.y(), first_leg.x());
  state.pose = {route[0].x(), route[0].y(), start_heading_rad};
  std::size_t target = 1;
  // Generous cap: the route length at a tenth of the speed.
  double length_m = 0;
  for (std::size_t i = 1; i < route.size(); ++i) length_m += (route[i] - route[i - 1]).norm();
  const double limit_s = std::min(options.max_duration_s, 10 * length_m / options.speed_mps + 60);
  while (true) {
    result.states.push_back(state);
    if (state.t_s + dt > limit_s + 1e-9) break;
    Eigen::Vector2d to_goal = route[target] - Eigen::Vector2d(state.pose.x_m, state.pose.y_m);
    while (to_goal.norm() < options.waypoint_tolerance_m && target + 1 < route.size()) {
      to_goal = route[++target] - Eigen::Vector2d(state.pose.x_m, state.pose.y_m);
    }
    const bool arrived = to_goal.norm() < options.waypoint_tolerance_m;
    const double docking_error = WrapAngle(start_heading_rad - state.pose.theta_rad);
    if (arrived && (!options.dock || (std::abs(docking_error) < options.dock_tolerance_rad &&
                                      state.linear_mps == 0))) {
      result.reached_goal = true;
      break;
    }
    const double error =
        arrived ? docking_error
                : WrapAngle(std::atan2(to_goal.y(), to_goal.x()) - state.pose.theta_rad);
    // Slow down for the last waypoint so the robot stops on it.
    const double wanted =
        arrived || std::abs(error) > options.turn_in_place_rad
            ? 0.0
            : std::min(options.speed_mps,
                       target + 1 == route.size() ? to_goal.norm() + 0.05 : options.speed_mps);
    const double dv = Clamp(wanted - state.linear_mps, options.max_acceleration_mps2 * dt);
    state.linear_mps += dv;
    state.angular_radps = Clamp(3.0 * error, options.max_angular_speed_radps);
    // Exact integration of a constant-twist arc over dt (midpoint heading).
    const double mid = state.pose.theta_rad + 0.5 * state.angular_radps * dt;
    state.pose.x_m += state.linear_mps * dt * std::cos(mid);
    state.pose.y_m += state.linear_mps * dt * std::sin(mid);
    state.pose.theta_rad = WrapAngle(state.pose.theta_rad + state.angular_radps * dt);
    state.t_s += dt;
    result.distance_m += state.linear_mps * dt;
  }
  return result;
}

PlanarPose InterpolatePose(const std::vector<RobotState>& states, double t_s) {
  if (states.empty()) return {};
  if (t_s <= states.front().t_s) return states.front().pose;
  if (t_s >= states.back().t_s) return states.back().pose;
  const double dt = states[1].t_s - states[0].t_s;
  const auto i =
      std::min(static_cast<std::size_t>((t_s - states.front().t_s) / dt), states.size() - 2);
  const double f = std::clamp((t_s - states[i].t_s) / dt, 0.0, 1.0);
  const PlanarPose& a = states[i].pose;
  const PlanarPose& b = states[i + 1].pose;
  return {a.x_m + f * (b.x_m - a.x_m), a.y_m + f * (b.y_m - a.y_m),
          WrapAngle(a.theta_rad + f * WrapAngle(b.theta_rad - a.theta_rad))};
}

Eigen::Isometry3d BasePose3(const PlanarPose& pose, const Terrain& terrain,
                            const std::vector<BumpSpec>& bumps, RollPitchYaw* rpy_out) {
  const Eigen::Vector2d p(pose.x_m, pose.y_m);
  const Eigen::Vector2d forward(std::cos(pose.theta_rad), std::sin(pose.theta_rad));
  const Eigen::Vector2d left(-forward.y(), forward.x());
  const Eigen::Vector2d gradient = terrain.GradientAt(p);
  // Climbing (slope > 0 ahead) lifts the nose: negative pitch in REP 103.
  RollPitchYaw rpy{std::atan(gradient.dot(left)), -std::atan(gradient.dot(forward)),
                   pose.theta_rad};
  for (const BumpSpec& bump : bumps) {
    const double d = (p - Eigen::Vector2d(bump.x_m, bump.y_m)).norm();
    if (d >= bump.radius_m) continue;
    const double c = std::cos(0.5 * std::numbers::pi * d / bump.radius_m);
    rpy.roll_rad += bump.roll_deg * kDegToRad * c * c;
    rpy.pitch_rad += bump.pitch_deg * kDegToRad * c * c;
  }
  if (rpy_out != nullptr) *rpy_out = rpy;
  return MakeIsometry({p.x(), p.y(), terrain.HeightAt(p)}, rpy);
}

}  // namespace littermap::sim

#pragma once
// The robot's route and motion: waypoints (given, or a lawnmower sweep of a polygon), a
// differential-drive robot following them (turn in place when far off heading, else drive with
// a proportional heading controller), and its 3D pose on the terrain: height from the height
// field, roll/pitch from the local slope plus bump events.

#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "core/planar_pose.hpp"
#include "core/pose3.hpp"
#include "sim/terrain.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim {

// The waypoints of a route: spec.waypoints_m, or boustrophedon lanes along x across the polygon
// (assumed convex), lane_spacing_m apart, entered 0.5 m inside its edges; with come_home, a last
// leg straight back to the first waypoint.
std::vector<Eigen::Vector2d> PlanRoute(const RouteSpec& spec);

struct RobotState {
  double t_s = 0;
  PlanarPose pose;        // T_world_base in the plane
  double linear_mps = 0;  // commanded (= true) wheel speeds
  double angular_radps = 0;
};

struct DriveOptions {
  double speed_mps = 0.6;
  double max_angular_speed_radps = 1.0;
  double max_acceleration_mps2 = 0.5;
  double rate_hz = 50;  // one state per 1/rate_hz
  double max_duration_s = std::numeric_limits<double>::infinity();
  double waypoint_tolerance_m = 0.15;
  double turn_in_place_rad = 0.5;  // heading error above which the robot stops and turns
  // Docking: at the last waypoint the robot turns in place until it faces the way it left.
  bool dock = false;
  double dock_tolerance_rad = 0.02;
};

struct DriveResult {
  std::vector<RobotState> states;  // from t = 0, the first at route[0] facing route[1]
  bool reached_goal = false;
  double distance_m = 0;
};

DriveResult DriveRoute(const std::vector<Eigen::Vector2d>& route, const DriveOptions& options);

// The planar pose at time t_s, linearly interpolated (heading on the circle); clamped at ends.
PlanarPose InterpolatePose(const std::vector<RobotState>& states, double t_s);

// Where the base stands in 3D: z on the terrain, roll/pitch from the slope under it plus the
// bumps it is on (a bump tilts by its roll/pitch times cos²(π/2 · d/radius) within its radius).
Eigen::Isometry3d BasePose3(const PlanarPose& pose, const Terrain& terrain,
                            const std::vector<BumpSpec>& bumps, RollPitchYaw* rpy = nullptr);

}  // namespace littermap::sim

#pragma once
// The description of a simulated park (samples/worlds/*.yaml) as plain option structs. The
// YAML gives sizes and counts; the world itself is generated from the seed (sim/world.hpp).
// Every key is optional (the defaults below) and an unknown key is an error naming the file and
// the key, so a typo never silently falls back to a default.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/mount.hpp"

namespace littermap::sim {

struct PathSpec {  // a dirt path: a polyline with a width
  std::vector<Eigen::Vector2d> points_m;
  double width_m = 1.5;
};

struct TerrainSpec {
  double hill_amplitude_m = 0.3;  // gentle slopes: sum of a few long sinusoids
  double hill_wavelength_m = 20;  // shortest wavelength of the hills
  int roots = 20;                 // small bumps (roots) of a few cm
  double root_height_m = 0.04;
  std::vector<PathSpec> paths;
  int leaf_patches = 6;    // leaf-litter ground regions
  int gravel_patches = 3;  // gravel ground regions
  double patch_radius_m = 3;
};

// Bounds on the counts of a world file (checked when it is read; park_small.yaml lists them).
inline constexpr int kMaxStructures = 20000;  // trees, rocks, benches, bins, fences, bushes each
inline constexpr int kMaxItems = 20000;       // litter.count, litter.daily_new, natural.count
// Runs start from 1970-01-01 to 2033-05-18 UTC (start_time_s, --start-time): the bag's stamps
// stay positive and ROS 2's int32 seconds hold a day-long run.
inline constexpr double kMaxStartTimeS = 2e9;
inline constexpr int kMaxRoots = 100000;    // terrain.roots
inline constexpr int kMaxPatches = 1000;    // leaf and gravel patches, open areas
inline constexpr int kMaxLitterDay = 3650;  // simulate --litter-day: ten years of days

struct StructureSpec {
  int trees = 30;
  int rocks = 10;
  int benches = 4;
  int bins = 3;
  int fence_segments = 4;  // fences and walls along the border
  int bushes = 10;
  int open_areas = 2;  // disks without any structure (few laser features)
  double open_area_radius_m = 6;
  double route_clearance_m = 1.0;  // free corridor half-width around the route
};

struct LitterSpec {
  int count = 60;
  double hotspot_fraction = 0.75;  // share placed around benches, bins and path edges
  double hotspot_sigma_m = 1.2;    // spread around a hotspot
  // Share of the items falling on grass that sink into it (long grass hides their lower part),
  // each by a share of its height drawn uniformly from [half_hidden_depth_min, _max].
  double half_hidden_fraction = 0.2;
  double half_hidden_depth_min = 0.3;
  double half_hidden_depth_max = 0.6;
  // Hard-to-see litter (sim/litter_wear.hpp), each share drawn per item from its own random
  // stream, so 0 (the default) leaves a world exactly as without these keys.
  double dirty_fraction = 0;         // items wet and soiled: darker, greyer, browner
  double crushed_fraction = 0;       // cans flattened to 20-40 % of their height
  double clear_bottle_fraction = 0;  // bottles of clear plastic: the ground shows through
  double on_gravel_fraction = 0;     // items dropped on a gravel patch (when there is one)
  // How the litter changes from day to day (WorldSpec::litter_day): each day park staff pick up
  // this share of it and visitors drop daily_new items more, in the same hotspot pattern.
  double daily_pickup_fraction = 0.3;
  int daily_new = 10;
  // TACO-aligned classes; weights are normalised. Keys: can, bottle, cup, carton,
  // food_container, plastic_bag, other.
  std::map<std::string, double> class_weights = {
      {"can", 0.15},           {"bottle", 0.2},       {"cup", 0.15},  {"carton", 0.1},
      {"food_container", 0.1}, {"plastic_bag", 0.15}, {"other", 0.15}};
};

struct NaturalSpec {
  int count = 80;
  // Keys: flower_red, flower_yellow, flower_white, flower_purple, leaf, stone, pine_cone,
  // branch, mushroom.
  std::map<std::string, double> class_weights = {
      {"flower_red", 0.08},    {"flower_yellow", 0.1}, {"flower_white", 0.1},
      {"flower_purple", 0.07}, {"leaf", 0.25},         {"stone", 0.15},
      {"pine_cone", 0.1},      {"branch", 0.1},        {"mushroom", 0.05}};
};

struct LaserSpec {
  std::string preset = "urg-04lx";  // urg-04lx | utm-30lx
  double rate_hz = 10;              // 10..40
  double range_noise_sigma_m = 0.01;
  double mixed_pixel_probability = 0.5;  // at a range edge, chance the beam averages both sides
  double dropout_probability = 0.002;    // spurious no-echo beams
  MountSpec mount{0.15, 0, 0.3, 0, 0, 0};
};

// The Kinect-like RGB-D camera (sim/rgbd_camera.hpp: 640x480, fx = fy = 525). Its clock is not
// synchronised with the laser's: frame k is exposed at clock_offset_ms + k / rate_hz + j_k with
// per-frame jitter j_k ~ N(0, jitter_sigma_ms) clipped to ±3σ (USB transfer and driver
// scheduling), and stamped with that exposure time; laser, odometry and IMU tick exactly on
// their periods from t = 0.
struct CameraSpec {
  double rate_hz = 10;  // 5..30 on a Kinect
  double clock_offset_ms = 13;
  double jitter_sigma_ms = 2;
  int jpeg_quality = 90;                   // colour JPEG, 1..100
  MountSpec mount{0.2, 0, 0.5, 0, 25, 0};  // camera body (x forward), pitched 25° down
};

struct OdometrySpec {  // wheel odometry errors (sim/odometry_model.hpp)
  double rate_hz = 50;
  double scale_error = 0.01;          // systematic distance error (wheel radius)
  double yaw_drift_deg_per_m = 0.15;  // systematic heading drift (track width)
  double translation_noise_m_per_sqrt_m = 0.01;
  double rotation_noise_deg_per_sqrt_m = 0.2;
};

struct ImuSpec {
  double rate_hz = 50;
  double tilt_noise_deg = 0.3;  // σ of roll and pitch
};

struct RobotSpec {
  LaserSpec laser;
  CameraSpec camera;
  OdometrySpec odometry;
  ImuSpec imu;
  double max_angular_speed_radps = 1.0;
};

struct RouteSpec {
  std::string type = "waypoints";  // waypoints | lawnmower
  std::vector<Eigen::Vector2d> waypoints_m;
  std::vector<Eigen::Vector2d> polygon_m;  // lawnmower: area to cover
  double lane_spacing_m = 4;
  double speed_mps = 0.6;  // 0.3..1.0
  // The survey ends where it started (at the dock): a last leg back to the first waypoint.
  bool come_home = false;
};

struct BumpSpec {  // a root or bump on the route that tilts the robot
  double x_m = 0, y_m = 0;
  double radius_m = 0.5;
  double roll_deg = 0, pitch_deg = 0;
  // Heading error the wheel odometry picks up crossing the bump (a wheel spinning or skidding
  // on the root), spread over the path within the radius: slip_deg per diameter driven.
  double slip_deg = 0;
};

struct TruthSpec {               // ground truth beside the bag (sim/ground_truth.hpp)
  int mask_every_n_frames = 10;  // instance mask of every n-th camera frame (from 0); 0: none
};

struct WorldSpec {
  std::filesystem::path source;  // the YAML file, for messages
  std::string name = "park";
  std::uint64_t seed = 1;
  double size_x_m = 40, size_y_m = 30;
  double start_time_s = 1.7e9;  // stamp of the first message
  TerrainSpec terrain;
  StructureSpec structure;
  LitterSpec litter;
  NaturalSpec natural;
  RobotSpec robot;
  RouteSpec route;
  // More routes through the same world (YAML `routes`, each with a name): the structure keeps
  // clear of every route, so driving any of them surveys the same park.
  std::vector<std::pair<std::string, RouteSpec>> routes;
  std::string driven_route;  // a name from `routes`; empty: `route`
  std::vector<BumpSpec> bumps;
  TruthSpec truth;
  // Seeds sensor noise, odometry drift and camera timing; none: `seed` does. The world itself
  // (terrain, objects) follows `seed` alone, so runs with different run seeds survey one park.
  std::optional<std::uint64_t> run_seed;
  // The day of the survey: day 0 has the litter `seed` places, each later day the litter of the
  // day before changed as `litter` says (deterministic in seed and day).
  int litter_day = 0;

  std::uint64_t RunSeed() const { return run_seed.value_or(seed); }
  // The route the robot drives. Throws BadInputError naming the known routes for an unknown name.
  const RouteSpec& DrivenRoute() const;
};

// Throws BadInputError naming the file and key on a malformed or unknown key, or an invalid
// value (e.g. "park.yaml: robot.laser.rate_hz: must be in [1, 100]").
WorldSpec LoadWorldSpec(const std::filesystem::path& path);
WorldSpec ParseWorldSpec(const std::string& yaml_text, const std::filesystem::path& source = {});

}  // namespace littermap::sim

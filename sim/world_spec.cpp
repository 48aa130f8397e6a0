#include "sim/world_spec.hpp"

#include "core/error.hpp"
#include "core/object_classes.hpp"
#include "core/text_file.hpp"
#include "core/yaml_fields.hpp"

namespace littermap::sim {
namespace {

const std::set<std::string> kLitterClasses(LitterClasses().begin(), LitterClasses().end());
const std::set<std::string> kNaturalClasses(NaturalClasses().begin(), NaturalClasses().end());

void Check(const YamlFields& fields, const char* key, bool ok, const std::string& what) {
  if (!ok) fields.Fail(key, what);
}

// A count of things in the world, bounded so that a typo (1e9 trees) is refused when the file is
// read instead of running until the memory is gone. The bounds hold a 2 km x 2 km world.
void ReadCount(YamlFields& fields, const char* key, int& value, int max) {
  fields.Read(key, value);
  Check(fields, key, value <= max, "must be at most " + std::to_string(max));
}

void ReadTerrain(YamlFields fields, TerrainSpec& terrain) {
  fields.Read("hill_amplitude_m", terrain.hill_amplitude_m);
  fields.Read("hill_wavelength_m", terrain.hill_wavelength_m);
  ReadCount(fields, "roots", terrain.roots, kMaxRoots);
  fields.Read("root_height_m", terrain.root_height_m);
  ReadCount(fields, "leaf_patches", terrain.leaf_patches, kMaxPatches);
  ReadCount(fields, "gravel_patches", terrain.gravel_patches, kMaxPatches);
  fields.Read("patch_radius_m", terrain.patch_radius_m);
  for (YamlFields& path_fields : fields.Children("paths")) {
    PathSpec path;
    path_fields.Read("points_m", path.points_m);
    path_fields.Read("width_m", path.width_m);
    Check(path_fields, "points_m", path.points_m.size() >= 2, "needs at least two points");
    path_fields.Finish();
    terrain.paths.push_back(path);
  }
  Check(fields, "hill_wavelength_m", terrain.hill_wavelength_m >= 2, "must be at least 2");
  fields.Finish();
}

void ReadStructure(YamlFields fields, StructureSpec& s) {
  ReadCount(fields, "trees", s.trees, kMaxStructures);
  ReadCount(fields, "rocks", s.rocks, kMaxStructures);
  ReadCount(fields, "benches", s.benches, kMaxStructures);
  ReadCount(fields, "bins", s.bins, kMaxStructures);
  ReadCount(fields, "fence_segments", s.fence_segments, kMaxStructures);
  ReadCount(fields, "bushes", s.bushes, kMaxStructures);
  ReadCount(fields, "open_areas", s.open_areas, kMaxPatches);
  fields.Read("open_area_radius_m", s.open_area_radius_m);
  fields.Read("route_clearance_m", s.route_clearance_m);
  fields.Finish();
}

// A share: a number in [0, 1] (finiteness is checked by YamlFields::Read).
void ReadShare(YamlFields& fields, const char* key, double& value) {
  fields.Read(key, value);
  Check(fields, key, value >= 0 && value <= 1, "must be in [0, 1]");
}

void ReadLitter(YamlFields fields, LitterSpec& litter) {
  ReadCount(fields, "count", litter.count, kMaxItems);
  ReadShare(fields, "hotspot_fraction", litter.hotspot_fraction);
  fields.Read("hotspot_sigma_m", litter.hotspot_sigma_m);
  ReadShare(fields, "half_hidden_fraction", litter.half_hidden_fraction);
  // An item sunk 90 % or more would be gone: nothing left to detect or to score.
  fields.Read("half_hidden_depth_min", litter.half_hidden_depth_min);
  fields.Read("half_hidden_depth_max", litter.half_hidden_depth_max);
  Check(fields, "half_hidden_depth_min",
        litter.half_hidden_depth_min >= 0 && litter.half_hidden_depth_min <= 0.9,
        "must be in [0, 0.9]");
  Check(fields, "half_hidden_depth_max",
        litter.half_hidden_depth_max >= litter.half_hidden_depth_min &&
            litter.half_hidden_depth_max <= 0.9,
        "must be in [half_hidden_depth_min, 0.9]");
  ReadShare(fields, "dirty_fraction", litter.dirty_fraction);
  ReadShare(fields, "crushed_fraction", litter.crushed_fraction);
  ReadShare(fields, "clear_bottle_fraction", litter.clear_bottle_fraction);
  ReadShare(fields, "on_gravel_fraction", litter.on_gravel_fraction);
  ReadShare(fields, "daily_pickup_fraction", litter.daily_pickup_fraction);
  ReadCount(fields, "daily_new", litter.daily_new, kMaxItems);
  fields.Read("class_weights", litter.class_weights, kLitterClasses);
  fields.Finish();
}

void ReadNatural(YamlFields fields, NaturalSpec& natural) {
  ReadCount(fields, "count", natural.count, kMaxItems);
  fields.Read("class_weights", natural.class_weights, kNaturalClasses);
  fields.Finish();
}

void ReadCamera(YamlFields fields, CameraSpec& camera) {
  fields.Read("rate_hz", camera.rate_hz);
  fields.Read("clock_offset_ms", camera.clock_offset_ms);
  fields.Read("jitter_sigma_ms", camera.jitter_sigma_ms);
  fields.Read("jpeg_quality", camera.jpeg_quality);
  ReadMount(fields.Child("mount"), camera.mount);
  Check(fields, "rate_hz", camera.rate_hz >= 1 && camera.rate_hz <= 60, "must be in [1, 60]");
  const double period_ms = 1000 / camera.rate_hz;
  Check(fields, "clock_offset_ms",
        camera.clock_offset_ms >= 0 && camera.clock_offset_ms < period_ms,
        "must be in [0, 1000 / rate_hz)");
  // 3σ below a sixth of the period keeps the frames in order and apart.
  Check(fields, "jitter_sigma_ms",
        camera.jitter_sigma_ms >= 0 && camera.jitter_sigma_ms * 18 <= period_ms,
        "must be in [0, 1000 / rate_hz / 18]");
  Check(fields, "jpeg_quality", camera.jpeg_quality >= 1 && camera.jpeg_quality <= 100,
        "must be in [1, 100]");
  fields.Finish();
}

void ReadTruth(YamlFields fields, TruthSpec& truth) {
  fields.Read("mask_every_n_frames", truth.mask_every_n_frames);  // 0: no masks
  fields.Finish();
}

void ReadRobot(YamlFields fields, RobotSpec& robot) {
  YamlFields laser = fields.Child("laser");
  laser.Read("preset", robot.laser.preset);
  laser.Read("rate_hz", robot.laser.rate_hz);
  laser.Read("range_noise_sigma_m", robot.laser.range_noise_sigma_m);
  laser.Read("mixed_pixel_probability", robot.laser.mixed_pixel_probability);
  laser.Read("dropout_probability", robot.laser.dropout_probability);
  ReadMount(laser.Child("mount"), robot.laser.mount);
  Check(laser, "preset", robot.laser.preset == "urg-04lx" || robot.laser.preset == "utm-30lx",
        "must be urg-04lx or utm-30lx");
  Check(laser, "rate_hz", robot.laser.rate_hz >= 1 && robot.laser.rate_hz <= 100,
        "must be in [1, 100]");
  laser.Finish();
  ReadCamera(fields.Child("camera"), robot.camera);
  YamlFields odometry = fields.Child("odometry");
  odometry.Read("rate_hz", robot.odometry.rate_hz);
  odometry.Read("scale_error", robot.odometry.scale_error);
  odometry.Read("yaw_drift_deg_per_m", robot.odometry.yaw_drift_deg_per_m);
  odometry.Read("translation_noise_m_per_sqrt_m", robot.odometry.translation_noise_m_per_sqrt_m);
  odometry.Read("rotation_noise_deg_per_sqrt_m", robot.odometry.rotation_noise_deg_per_sqrt_m);
  Check(odometry, "rate_hz", robot.odometry.rate_hz >= 1 && robot.odometry.rate_hz <= 1000,
        "must be in [1, 1000]");
  odometry.Finish();
  YamlFields imu = fields.Child("imu");
  imu.Read("rate_hz", robot.imu.rate_hz);
  imu.Read("tilt_noise_deg", robot.imu.tilt_noise_deg);
  Check(imu, "rate_hz", robot.imu.rate_hz >= 1 && robot.imu.rate_hz <= 1000,
        "must be in [1, 1000]");
  imu.Finish();
  fields.Read("max_angular_speed_radps", robot.max_angular_speed_radps);
  fields.Finish();
}

void ReadRoute(YamlFields fields, RouteSpec& route) {
  fields.Read("type", route.type);
  fields.Read("waypoints_m", route.waypoints_m);
  fields.Read("polygon_m", route.polygon_m);
  fields.Read("lane_spacing_m", route.lane_spacing_m);
  fields.Read("speed_mps", route.speed_mps);
  fields.Read("come_home", route.come_home);
  Check(fields, "type", route.type == "waypoints" || route.type == "lawnmower",
        "must be waypoints or lawnmower");
  Check(fields, "speed_mps", route.speed_mps >= 0.05 && route.speed_mps <= 3,
        "must be in "
        "[0.05, 3]");
  if (route.type == "waypoints") {
    Check(fields, "waypoints_m", route.waypoints_m.size() >= 2, "needs at least two points");
  } else {
    Check(fields, "polygon_m", route.polygon_m.size() >= 3, "needs at least three points");
    Check(fields, "lane_spacing_m", route.lane_spacing_m >= 0.5, "must be at least 0.5");
  }
  fields.Finish();
}

void ReadBumps(YamlFields& fields, std::vector<BumpSpec>& bumps) {
  for (YamlFields& bump_fields : fields.Children("bumps")) {
    BumpSpec bump;
    bump_fields.Read("x_m", bump.x_m);
    bump_fields.Read("y_m", bump.y_m);
    bump_fields.Read("radius_m", bump.radius_m);
    bump_fields.Read("roll_deg", bump.roll_deg);
    bump_fields.Read("pitch_deg", bump.pitch_deg);
    bump_fields.Read("slip_deg", bump.slip_deg);
    Check(bump_fields, "radius_m", bump.radius_m > 0.05, "must be above 0.05");
    Check(bump_fields, "roll_deg", std::abs(bump.roll_deg) <= 30, "must be within ±30");
    Check(bump_fields, "pitch_deg", std::abs(bump.pitch_deg) <= 30, "must be within ±30");
    Check(bump_fields, "slip_deg", std::abs(bump.slip_deg) <= 45, "must be within ±45");
    bump_fields.Finish();
    bumps.push_back(bump);
  }
}

}  // namespace

WorldSpec ParseWorldSpec(const std::string& yaml_text, const std::filesystem::path& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw BadInputError(source.string() + ": not valid YAML: " + e.what());
  }
  WorldSpec spec;
  spec.source = source;
  YamlFields fields(root, source, "");
  fields.Read("name", spec.name);
  fields.Read("seed", spec.seed);
  fields.Read("size_x_m", spec.size_x_m);
  fields.Read("size_y_m", spec.size_y_m);
  fields.Read("start_time_s", spec.start_time_s);
  Check(fields, "size_x_m", spec.size_x_m >= 5 && spec.size_x_m <= 2000, "must be in [5, 2000]");
  Check(fields, "size_y_m", spec.size_y_m >= 5 && spec.size_y_m <= 2000, "must be in [5, 2000]");
  Check(fields, "start_time_s", spec.start_time_s >= 0 && spec.start_time_s < kMaxStartTimeS,
        "must be in [0, 2e9): 1970-01-01 to 2033-05-18");
  ReadTerrain(fields.Child("terrain"), spec.terrain);
  ReadStructure(fields.Child("structure"), spec.structure);
  ReadLitter(fields.Child("litter"), spec.litter);
  ReadNatural(fields.Child("natural"), spec.natural);
  ReadRobot(fields.Child("robot"), spec.robot);
  ReadRoute(fields.Child("route"), spec.route);
  for (YamlFields& route_fields : fields.Children("routes")) {
    std::string name;
    route_fields.Read("name", name);
    Check(route_fields, "name", !name.empty() && name != "route", "must be a non-empty name");
    for (const auto& [known, unused] : spec.routes) {
      Check(route_fields, "name", known != name, "'" + name + "' is used twice");
    }
    RouteSpec route;
    ReadRoute(route_fields, route);
    spec.routes.emplace_back(name, route);
  }
  ReadBumps(fields, spec.bumps);
  ReadTruth(fields.Child("truth"), spec.truth);
  fields.Finish();
  return spec;
}

const RouteSpec& WorldSpec::DrivenRoute() const {
  if (driven_route.empty() || driven_route == "route") return route;
  std::string known = "route";
  for (const auto& [route_name, named_route] : routes) {
    if (route_name == driven_route) return named_route;
    known += ", " + route_name;
  }
  throw BadInputError(source.string() + ": no route named '" + driven_route +
                      "' (routes: " + known + ")");
}

WorldSpec LoadWorldSpec(const std::filesystem::path& path) {
  return ParseWorldSpec(ReadTextFile(path), path);
}

}  // namespace littermap::sim

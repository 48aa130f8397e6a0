#include "sim/ground_truth.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"

namespace littermap::sim {
namespace {

using nlohmann::json;

std::string Format(const char* format, auto... values) {
  char line[256];
  std::snprintf(line, sizeof line, format, values...);
  return line;
}

std::size_t WriteObjects(const std::filesystem::path& path, const World& world, ObjectKind kind) {
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "id,class,x,y,z,size_m\n";
  std::size_t count = 0;
  for (const WorldObject& o : world.objects) {
    if (o.kind != kind) continue;
    out << Format("%d,%s,%.4f,%.4f,%.4f,%.4f\n", o.id, o.label.c_str(), o.center_m.x(),
                  o.center_m.y(), o.center_m.z(), o.size());
    ++count;
  }
  file.Commit();
  return count;
}

json Vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
json Vec(const Eigen::Vector2d& v) { return json::array({v.x(), v.y()}); }

json ObjectJson(const WorldObject& o) {
  json object = {{"id", o.id},
                 {"group", o.group},
                 {"kind", ObjectKindName(o.kind)},
                 {"class", o.label},
                 {"shape", ShapeName(o.shape)},
                 {"center_m", Vec(o.center_m)},
                 {"rpy_rad", json::array({o.orientation.roll_rad, o.orientation.pitch_rad,
                                          o.orientation.yaw_rad})},
                 {"size_m", Vec(o.size_m)},
                 {"colour_rgb", Vec(o.colour_rgb)},
                 {"texture", o.texture},
                 {"hidden_fraction", o.hidden_fraction}};
  // Wear of hard-to-see litter, only where there is some: worlds without it write what they
  // always wrote.
  if (o.dirt > 0) object["dirt"] = o.dirt;
  if (o.transmission > 0) object["transmission"] = o.transmission;
  if (o.crushed) object["crushed"] = true;
  return object;
}

json TerrainJson(const Terrain& terrain) {
  json waves = json::array(), roots = json::array(), patches = json::array(), paths = json::array();
  for (const HeightWave& w : terrain.waves()) {
    waves.push_back({{"direction", Vec(w.direction)},
                     {"amplitude_m", w.amplitude_m},
                     {"wavelength_m", w.wavelength_m},
                     {"phase_rad", w.phase_rad}});
  }
  for (const Root& r : terrain.roots()) {
    roots.push_back(
        {{"center_m", Vec(r.center_m)}, {"height_m", r.height_m}, {"sigma_m", r.sigma_m}});
  }
  for (const GroundPatch& p : terrain.patches()) {
    patches.push_back({{"ground", GroundTypeName(p.type)},
                       {"center_m", Vec(p.center_m)},
                       {"radius_m", p.radius_m},
                       {"phase_rad", p.phase_rad}});
  }
  for (const PathSpec& p : terrain.paths()) {
    json points = json::array();
    for (const Eigen::Vector2d& q : p.points_m) points.push_back(Vec(q));
    paths.push_back({{"ground", "dirt_path"}, {"points_m", points}, {"width_m", p.width_m}});
  }
  return {{"height",
           "sum of waves amplitude*sin(direction.p*2pi/wavelength+phase) + roots "
           "height*exp(-|p-center|^2/(2 sigma^2))"},
          {"default_ground", "grass"},
          {"waves", waves},
          {"roots", roots},
          {"patches", patches},
          {"paths", paths}};
}

json Pose(const Eigen::Isometry3d& T) {
  const RollPitchYaw rpy = RpyFromRotation(T.linear());
  return {{"xyz_m", Vec(Eigen::Vector3d(T.translation()))},
          {"rpy_rad", json::array({rpy.roll_rad, rpy.pitch_rad, rpy.yaw_rad})}};
}

json WorldJson(const Simulation& simulation) {
  const World& world = simulation.world();
  json objects = json::array(), route = json::array(), bumps = json::array();
  for (const WorldObject& o : world.objects) objects.push_back(ObjectJson(o));
  for (const Eigen::Vector2d& p : world.route_m) route.push_back(Vec(p));
  for (const BumpSpec& b : world.spec.bumps) {
    bumps.push_back({{"center_m", json::array({b.x_m, b.y_m})},
                     {"radius_m", b.radius_m},
                     {"roll_deg", b.roll_deg},
                     {"pitch_deg", b.pitch_deg},
                     {"slip_deg", b.slip_deg}});
  }
  return {{"name", world.spec.name},
          {"seed", world.spec.seed},
          {"run_seed", world.spec.RunSeed()},
          {"litter_day", world.spec.litter_day},
          {"route", world.spec.driven_route.empty() ? "route" : world.spec.driven_route},
          {"size_m", json::array({world.spec.size_x_m, world.spec.size_y_m})},
          {"frame", "world: x east, y north, z up; the robot starts at route[0]"},
          {"terrain", TerrainJson(world.terrain)},
          {"objects", objects},
          {"route_m", route},
          {"bumps", bumps},
          {"T_base_laser", Pose(simulation.T_base_laser())},
          {"T_base_camera_body", Pose(simulation.T_base_camera())},
          {"T_base_camera_optical", Pose(simulation.T_base_optical())},
          {"camera",
           {{"rate_hz", world.spec.robot.camera.rate_hz},
            {"clock_offset_ms", world.spec.robot.camera.clock_offset_ms},
            {"jitter_sigma_ms", world.spec.robot.camera.jitter_sigma_ms},
            {"frames", simulation.camera_frame_count()}}},
          {"instance_masks",
           {{"every_n_frames", world.spec.truth.mask_every_n_frames},
            {"index", "masks/index.csv (frame,stamp_ns,file)"},
            {"values", "16-bit PNG: 0 ground, 65535 sky, otherwise object id + 1"}}},
          {"duration_s", simulation.duration_s()},
          {"distance_m", simulation.drive().distance_m}};
}

}  // namespace

GroundTruthResult WriteGroundTruth(const std::filesystem::path& directory,
                                   const Simulation& simulation, double start_time_s) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw FileFailure(directory, "cannot create", error.value());
  GroundTruthResult result;
  const auto tum_path = directory / "trajectory.tum";
  OutputFile tum_file(tum_path);
  std::ostream& tum = tum_file.stream();
  tum << "# timestamp tx ty tz qx qy qz qw (true base_link in world)\n";
  for (const RobotState& state : simulation.states()) {
    const Eigen::Isometry3d T = simulation.TrueBasePose(state.t_s);
    const Eigen::Quaterniond q(T.linear());
    tum << Format("%.6f %.5f %.5f %.5f %.6f %.6f %.6f %.6f\n", start_time_s + state.t_s,
                  T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(),
                  q.z(), q.w());
    ++result.poses;
  }
  tum_file.Commit();
  result.litter = WriteObjects(directory / "litter.csv", simulation.world(), ObjectKind::kLitter);
  result.natural =
      WriteObjects(directory / "natural.csv", simulation.world(), ObjectKind::kNatural);
  WriteFileAtomically(
      directory / "world.json",
      WorldJson(simulation).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  return result;
}

}  // namespace littermap::sim

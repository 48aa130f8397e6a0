#include "sim/truth_map.hpp"

#include "core/pose3.hpp"
#include "reconstruct/occupancy_grid.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::sim {

void WriteTruthMap(const Simulation& simulation, const std::filesystem::path& truth_dir) {
  const PlanarPose T_base_laser = ToPlanar(simulation.T_base_laser());
  reconstruct::ScanPointsOptions points;
  points.laser_height_m = simulation.T_base_laser().translation().z();
  reconstruct::OccupancyGrid grid({});
  const WorldSpec& spec = simulation.world().spec;
  grid.Cover({-1, -1}, {spec.size_x_m + 1, spec.size_y_m + 1});  // the park, allocated once
  for (std::size_t k = 0; k < simulation.scan_count(); ++k) {
    const double t_s = simulation.ScanTime(k);
    RollPitchYaw rpy;
    const PlanarPose T_world_base = ToPlanar(simulation.TrueBasePose(t_s, &rpy));
    const reconstruct::ScanPoints scan = reconstruct::ScanToPoints(
        simulation.Scan(k), T_base_laser, points, reconstruct::Tilt{rpy.roll_rad, rpy.pitch_rad});
    reconstruct::Points2 hits;
    hits.reserve(scan.points_base.size());
    for (const Eigen::Vector2d& p : scan.points_base) {
      hits.push_back(reconstruct::Transform(T_world_base, p));
    }
    const PlanarPose T_world_laser = Compose(T_world_base, T_base_laser);
    grid.InsertScan({T_world_laser.x_m, T_world_laser.y_m}, hits);
  }
  grid.WritePgmYaml(truth_dir / "map.pgm", truth_dir / "map.yaml");
}

}  // namespace littermap::sim

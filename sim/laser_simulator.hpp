#pragma once
// A 2D laser scanner in a 3D world: every beam is a ray in the (possibly tilted) laser plane,
// cast against the world's primitives and the terrain, so a robot pitched by a bump sees the
// ground. Sensor effects: Gaussian range noise, no-echo beams (+inf, REP 117) beyond range or
// as random dropouts, and mixed pixels at range edges (the reading lands between the near and
// the far surface, as on real Hokuyo scanners).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/laser_scan.hpp"
#include "sim/world.hpp"

namespace littermap::sim {

struct LaserModel {
  std::string name;
  double fov_rad = 0;
  int beams = 0;
  double range_min_m = 0;
  double range_max_m = 0;
};

// "urg-04lx": 240°, 682 beams, 0.02–5.6 m; "utm-30lx": 270°, 1081 beams, 0.1–30 m (Hokuyo data
// sheets). Throws UsageError for another name.
LaserModel LaserPreset(const std::string& name);

struct LaserSimulatorOptions {
  LaserModel model = LaserPreset("urg-04lx");
  double range_noise_sigma_m = 0.01;
  double mixed_pixel_probability = 0.5;
  double dropout_probability = 0.002;
  double edge_jump_m = 0.3;  // neighbouring ranges differing by more form an edge
};

class LaserSimulator {
 public:
  LaserSimulator(const World& world, LaserSimulatorOptions options);

  // One scan from T_world_laser; noise drawn from (seed, scan_index), so any scan can be
  // recomputed on its own.
  LaserScan Scan(const Eigen::Isometry3d& T_world_laser, TimestampNs stamp_ns, std::uint64_t seed,
                 std::uint64_t scan_index) const;
  // Exact distance along the unit ray to the first surface, or +inf within max_range_m.
  double CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                 double max_range_m) const;

  const LaserSimulatorOptions& options() const { return options_; }

 private:
  struct Primitive {
    Shape shape;
    Eigen::Matrix3d R_object_world;
    Eigen::Vector3d center_m;
    Eigen::Vector3d half_size_m;
    double bounding_radius_m;
  };
  double CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                 double max_range_m, const std::vector<const Primitive*>& candidates) const;
  std::vector<std::vector<const Primitive*>> CandidatesPerBeam(
      const Eigen::Isometry3d& T_world_laser, const LaserScan& scan) const;
  double CastTerrain(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                     double max_range_m) const;

  const World& world_;
  LaserSimulatorOptions options_;
  std::vector<Primitive> primitives_;
  double max_terrain_height_m_ = 0;
};

}  // namespace littermap::sim

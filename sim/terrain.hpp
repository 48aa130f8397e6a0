#pragma once
// The park's ground: a smooth height field (gentle hills from a few long sinusoids plus small
// Gaussian bumps for roots) and ground-texture regions (dirt paths, gravel and leaf-litter patches
// on grass). Both are queryable anywhere, so the laser can hit the ground and a renderer can later
// shade it.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/world_spec.hpp"

namespace littermap::sim {

enum class GroundType { kGrass, kDirtPath, kLeafLitter, kGravel };
const char* GroundTypeName(GroundType type);

struct HeightWave {           // amplitude_m * sin(direction · p * 2π / wavelength_m + phase_rad)
  Eigen::Vector2d direction;  // unit
  double amplitude_m = 0;
  double wavelength_m = 1;
  double phase_rad = 0;
};

struct Root {  // height_m * exp(-|p - center|² / (2 sigma_m²))
  Eigen::Vector2d center_m;
  double height_m = 0;
  double sigma_m = 0.1;
};

struct GroundPatch {  // a disk with a wavy rim: r(φ) = radius_m * (1 + 0.2 sin(3φ + phase))
  GroundType type = GroundType::kGrass;
  Eigen::Vector2d center_m;
  double radius_m = 1;
  double phase_rad = 0;
};

class Terrain {
 public:
  Terrain(const WorldSpec& spec, std::uint64_t seed);
  // A flat terrain (height 0, grass) for tests.
  Terrain() = default;

  double HeightAt(const Eigen::Vector2d& p) const;
  // The hills alone (no roots), their slope bound, and the most the roots add on top.
  double HillHeightAt(const Eigen::Vector2d& p) const;
  double RootHeightAt(const Eigen::Vector2d& p) const;  // HeightAt = HillHeightAt + RootHeightAt
  double max_hill_slope() const { return max_hill_slope_; }
  double max_root_height_m() const { return max_root_height_m_; }
  Eigen::Vector2d GradientAt(const Eigen::Vector2d& p) const;
  GroundType GroundAt(const Eigen::Vector2d& p) const;
  // An upper bound of |gradient| anywhere, for safe ray marching.
  double max_slope() const { return max_slope_; }
  // Distance from p to the nearest path centre line minus half its width (< 0: on a path).
  double DistanceToPathEdge(const Eigen::Vector2d& p) const;

  const std::vector<HeightWave>& waves() const { return waves_; }
  const std::vector<Root>& roots() const { return roots_; }
  const std::vector<GroundPatch>& patches() const { return patches_; }
  const std::vector<PathSpec>& paths() const { return paths_; }

 private:
  // Indices of the roots that reach into each 1 m cell, so a height query looks at a few roots
  // rather than all of them.
  const std::vector<int>& RootsNear(const Eigen::Vector2d& p) const;

  std::vector<HeightWave> waves_;
  std::vector<Root> roots_;
  std::vector<std::vector<int>> root_cells_;
  int cells_x_ = 0, cells_y_ = 0;
  std::vector<GroundPatch> patches_;
  std::vector<PathSpec> paths_;
  double max_slope_ = 0;
  double max_hill_slope_ = 0;
  double max_root_height_m_ = 0;
};

// Distance from p to segment ab.
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b);

}  // namespace littermap::sim

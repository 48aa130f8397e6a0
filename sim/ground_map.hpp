#pragma once
// What the renderer needs to know about the ground that is too slow to ask the Terrain per
// pixel, precomputed once per world on a regular grid: the ground type (grass, dirt path, leaf
// litter, gravel) at 2.5 cm, with ragged region borders, and how much direct sunlight reaches each
// 10 cm cell past the trees, bushes, benches and walls (shadows cast along the sun direction,
// dappled under crowns) and past slowly varying cloud shade.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/world.hpp"

namespace littermap::sim {

class GroundMap {
 public:
  // sun_direction_world points towards the sun (unit, z > 0).
  GroundMap(const World& world, const Eigen::Vector3d& sun_direction_world);

  // The ground type at (x, y); grass outside the park. Region borders are ragged at metre and
  // decimetre scale (RaggedGroundPoint) and wobble at the scale of the cells.
  GroundType TypeAt(float x, float y) const;
  // Share of direct sun reaching the ground at (x, y): 1 in full sun, ~0.05 behind an opaque
  // object, dappled 0.1..0.4 under a tree crown, times the cloud shade. Bilinear, so shadow
  // edges are soft.
  float SunlightAt(float x, float y) const;

 private:
  std::uint8_t Cell(float x, float y) const;  // types_ entry, flag included
  void MarkBorders();
  void BakeSunlight();
  void CastShadow(const World& world, const WorldObject& object, const Eigen::Vector3d& sun);
  void Stamp(const Eigen::Vector2d& centre_m, double radius_m, float occlusion);

  float origin_x_m_ = 0, origin_y_m_ = 0;
  float type_cell_m_ = 0.025f;
  int type_cols_ = 0, type_rows_ = 0;
  std::vector<std::uint8_t> types_;
  float shadow_cell_m_ = 0.1f;
  int shadow_cols_ = 0, shadow_rows_ = 0;
  std::vector<float> sunlight_;  // occlusion while shadows are cast, then sunlight
};

// Slow cloud shade at world (x, y): 1 under a clear sky, down to 0.55 in a cloud's shadow.
float CloudLight(float x, float y);

}  // namespace littermap::sim

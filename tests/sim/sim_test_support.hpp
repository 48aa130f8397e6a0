#pragma once
// Shared helpers of the simulator tests: the sample world and a tiny hand-made world.

#include <filesystem>

#include "sim/world.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim::testing {

inline std::filesystem::path SampleWorld(const char* name = "park_small.yaml") {
  return std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / name;
}

// A flat, empty world (height 0 everywhere) to put single primitives into.
inline World EmptyWorld() {
  World world;
  world.spec.size_x_m = 50;
  world.spec.size_y_m = 50;
  world.spec.terrain.root_height_m = 0;
  return world;
}

inline WorldObject MakePrimitive(Shape shape, const Eigen::Vector3d& center_m,
                                 const Eigen::Vector3d& size_m, double yaw_rad = 0) {
  WorldObject object;
  object.kind = ObjectKind::kRock;
  object.shape = shape;
  object.center_m = center_m;
  object.size_m = size_m;
  object.orientation.yaw_rad = yaw_rad;
  return object;
}

}  // namespace littermap::sim::testing

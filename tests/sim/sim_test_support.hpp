#pragma once
// Shared helpers of the simulator tests: the sample world and a tiny hand-made world.

#include <filesystem>

#include "sim/world.hpp"
#include "sim/world_spec.hpp"
#include "support/test_files.hpp"

namespace littermap::test {

// A flat, empty world (height 0 everywhere) to put single primitives into.
inline sim::World EmptyWorld() {
  sim::World world;
  world.spec.size_x_m = 50;
  world.spec.size_y_m = 50;
  world.spec.terrain.root_height_m = 0;
  return world;
}

inline sim::WorldObject MakePrimitive(sim::Shape shape, const Eigen::Vector3d& center_m,
                                      const Eigen::Vector3d& size_m, double yaw_rad = 0) {
  sim::WorldObject object;
  object.kind = sim::ObjectKind::kRock;
  object.shape = shape;
  object.center_m = center_m;
  object.size_m = size_m;
  object.orientation.yaw_rad = yaw_rad;
  return object;
}

}  // namespace littermap::test

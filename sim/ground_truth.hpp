#pragma once
// The ground truth of a simulated run, in TRUTH_DIR:
//   trajectory.tum  true base_link pose in the world, one per odometry step (TUM: t x y z q)
//   litter.csv      id,class,x,y,z,size_m of every litter item (world frame, metres)
//   natural.csv     the same for the natural look-alikes (flowers, leaves, stones, ...)
//   world.json      everything: terrain, every primitive, route, bumps, sensor mounts, camera
//   masks/          instance masks of every n-th camera frame (sim/instance_masks.hpp; written
//                   while recording, by the recorder)

#include <filesystem>

#include "sim/simulation.hpp"

namespace littermap::sim {

struct GroundTruthResult {
  std::size_t poses = 0;
  std::size_t litter = 0;
  std::size_t natural = 0;
};

// Creates `directory` if needed. Throws InternalError when a file cannot be written.
GroundTruthResult WriteGroundTruth(const std::filesystem::path& directory,
                                   const Simulation& simulation, double start_time_s);

}  // namespace littermap::sim

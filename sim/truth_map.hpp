#pragma once
// The simulator's ground-truth occupancy map: every scan of the run inserted at the robot's true
// pose, echoes of tilted beams that reach the ground dropped (true roll and pitch), written as
// TRUTH_DIR/map.pgm + map.yaml like `reconstruct` writes its map. With it a site built from
// simulator truth has a site map: later runs register onto it, density.png shows its trees.

#include <filesystem>

#include "sim/simulation.hpp"

namespace littermap::sim {

void WriteTruthMap(const Simulation& simulation, const std::filesystem::path& truth_dir);

}  // namespace littermap::sim

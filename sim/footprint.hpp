#pragma once
// The ground a small object (litter, a look-alike) covers, seen from above: the rectangle around
// its horizontal extent, aligned with its heading. Two objects whose footprints overlap would
// share space: a bottle through a bottle renders as one odd object and scores as a miss.

#include <Eigen/Core>

#include "sim/world.hpp"

namespace littermap::sim {

struct Footprint {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d size_m = Eigen::Vector2d::Zero();  // along the heading, across it
  double yaw_rad = 0;
};

// The footprint of `object` as posed (standing or lying, any heading).
Footprint FootprintOf(const WorldObject& object);

// True when `a` and `b` come closer than `gap_m` (each grown by half of it).
bool FootprintsOverlap(const Footprint& a, const Footprint& b, double gap_m);

}  // namespace littermap::sim

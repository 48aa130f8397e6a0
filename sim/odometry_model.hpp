#pragma once
// Wheel odometry with realistic drift. Between consecutive true poses the relative motion
// (dx, dy, dθ) over distance d is corrupted by
//   systematic: dx, dy scaled by (1 + scale_error); dθ += yaw_drift · d
//   random:     dx, dy += N(0, σ_t² d); dθ += N(0, σ_r² d)
// and integrated from the first true pose. The random part's variance grows linearly with the
// distance driven, whatever the step size (a random walk per metre), so after D metres on a
// straight line the heading error has mean yaw_drift·D and standard deviation σ_r·√D.
// On a bump the wheels slip: a step within its radius adds slip_deg · d / (2 · radius) to dθ.

#include <cstdint>
#include <vector>

#include "core/planar_pose.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim {

std::vector<PlanarPose> SimulateOdometry(const std::vector<PlanarPose>& truth,
                                         const OdometrySpec& spec, std::uint64_t seed,
                                         const std::vector<BumpSpec>& bumps = {});

}  // namespace littermap::sim

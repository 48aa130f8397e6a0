#pragma once
// Synthetic wheel odometry for logs that carry none (the corrected Radish logs), made as
// shared/datasets/README.md prescribes: take the reference poses, compute the relative motion
// (dx, dy, dθ) between consecutive poses in the earlier pose's frame, corrupt it with seeded
// Gaussian noise (σ = 5 % of the distance d for dx and for dy, σ = 5 % of |dθ| + 1°·d/m + 0.1°
// for dθ) and integrate from the first reference pose.
//
// Reproducible across platforms: std::normal_distribution is implementation-defined, so the
// normal samples come from std::mt19937_64 (fully specified by the standard) through an explicit
// Box–Muller transform. Per step the draws are, in order, the noise of dx, dy and dθ.

#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "core/planar_pose.hpp"

namespace littermap::importers {

// Standard normal samples: Box–Muller on pairs of 53-bit uniforms from std::mt19937_64, both
// outputs of a pair used (cos first, then sin).
class GaussianSampler {
 public:
  explicit GaussianSampler(std::uint64_t seed) : engine_(seed) {}
  double Next();

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

struct OdometryNoiseOptions {
  double translation_sigma_per_m = 0.05;                     // σ of dx and of dy per metre of d
  double rotation_sigma_per_rad = 0.05;                      // σ of dθ per radian of |dθ|
  double rotation_sigma_per_m_rad = std::numbers::pi / 180;  // 1° per metre of d
  double rotation_sigma_floor_rad = 0.1 * std::numbers::pi / 180;  // 0.1° on every step
};

// One corrupted odometry pose per reference pose; the first equals the first reference pose.
// Throws UsageError for negative sigmas.
std::vector<PlanarPose> CorruptOdometry(std::span<const PlanarPose> reference, std::uint64_t seed,
                                        const OdometryNoiseOptions& options = {});

}  // namespace littermap::importers

#pragma once
// The ground of one frame (thesis 3.1, step 2, "chosen strictly"): the largest connected
// component whose mean normal is near vertical and which lies near the wheels' level, joined by
// the other large ground-like components that lie on the same surface (a path behind a grass
// edge). The surface is a quadratic height field z = f(x, y) in the levelled frame, fitted
// robustly, so gentle slopes and hills do not count as objects.

#include <vector>

#include <Eigen/Core>

#include "detect/connected_components.hpp"
#include "detect/organized_cloud.hpp"

namespace littermap::detect {

struct GroundOptions {
  double max_tilt_deg = 25.0;         // mean normal of a ground component vs vertical
  double max_level_offset_m = 0.5;    // |mean height| of a ground component (base_link at z = 0)
  int min_component_points = 1500;    // the seed component
  int min_joined_points = 300;        // further components joined to it
  double max_join_residual_m = 0.04;  // median |height above the fit| of a joined component
  int max_fit_points = 4000;          // subsample for the least-squares fit
  // Strictness: a ground point lies within this band of the fitted surface, widened by the depth
  // noise (2 sigma, sigma = depth_noise_per_m2 z^2); the rest of its component (a kerb, the foot
  // of a wall the normals let through) is not ground.
  double inlier_band_m = 0.04;
  double depth_noise_per_m2 = 1.5e-3;
  void Validate() const;
};

class GroundSurface {
 public:
  // z = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2
  using Coefficients = Eigen::Matrix<double, 6, 1>;
  GroundSurface() = default;
  explicit GroundSurface(const Coefficients& c) : c_(c) {}
  double HeightAt(double x, double y) const {
    return c_[0] + c_[1] * x + c_[2] * y + c_[3] * x * x + c_[4] * x * y + c_[5] * y * y;
  }
  double HeightAbove(const Eigen::Vector3f& p) const { return p.z() - HeightAt(p.x(), p.y()); }
  const Coefficients& coefficients() const { return c_; }

 private:
  Coefficients c_ = Coefficients::Zero();
};

struct GroundResult {
  bool found = false;
  GroundSurface surface;
  std::vector<unsigned char> is_ground;  // per pixel: member of a ground component
  std::size_t points = 0;
  std::size_t components_joined = 0;
  double rms_residual_m = 0;
};

GroundResult FindGround(const OrganizedCloud& cloud, const Components& components,
                        const GroundOptions& options);

}  // namespace littermap::detect

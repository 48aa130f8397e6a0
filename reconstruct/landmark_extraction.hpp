#pragma once
// Landmarks from one laser scan: round obstacles (tree trunks, posts, bins) as circles. A trunk
// seen from the other side is an arc on the other side of it, so a scan matcher that overlays
// echoes finds a place offset by up to a trunk's diameter, or nothing; the centre of the circle
// through the arc is the same from every side. Park-scale loops are closed on these centres
// (reconstruct/landmark_map.hpp).
//
// The scan's points, in beam order, are cut into segments where consecutive echoes jump apart
// (further than a few beam spacings at their range). A segment of enough echoes gets a circle:
// the algebraic fit of Kasa (1976), minimising sum (x^2 + y^2 + D x + E y + F)^2, linear and
// closed-form but biased toward small radii on short arcs, refined by Gauss-Newton on the
// geometric distances d_i = |p_i - c| - r. The circle is kept if
//   - its radius is a trunk's (a wall or a fence fits a huge radius, a table leg a tiny one),
//   - the echoes lie on it (RMS of d_i), and the arc bulges enough to tell it from a straight
//     piece (its sagitta against the RMS),
//   - its centre lies behind the echoes as seen from the laser (a convex obstacle, not the
//     inside of a corner).
// The centre's covariance is the Gauss-Newton one (J^T J)^-1 sigma^2 with sigma the larger of
// the fit's RMS and the range noise, plus a floor for what a circle does not model (bark, a
// trunk that is not round).

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct LandmarkExtractionOptions {
  std::size_t min_points = 6;
  double min_radius_m = 0.06;
  double max_radius_m = 0.6;
  double max_rms_residual_m = 0.02;
  double min_sagitta_rms = 3;  // the arc's sagitta at least this many RMS residuals
  double max_range_m = 25;     // farther arcs have too few echoes to fit
  // Consecutive echoes further apart than this, or this many beam spacings at their range, are
  // in different segments.
  double segment_gap_m = 0.1;
  double segment_gap_beams = 4;
  double range_sigma_m = 0.01;         // the scanner's range noise, a floor under the fit's RMS
  double centre_sigma_floor_m = 0.02;  // added to the centre's standard deviation (both axes)
  void Validate() const;
};

struct LandmarkObservation {
  Eigen::Vector2d centre_base = Eigen::Vector2d::Zero();
  double radius_m = 0;
  Eigen::Matrix2d covariance_base = Eigen::Matrix2d::Identity();  // of the centre
  double rms_residual_m = 0;
  std::size_t points = 0;
};

struct CircleFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0;
  double rms_residual_m = 0;
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();  // J^T J of (cx, cy, r)
  bool ok = false;  // a circle was found (not a straight line, numerically sound)
};

// Least-squares circle through the points (Kasa's fit refined by Gauss-Newton).
CircleFit FitCircle(const Points2& points);

// points_base: the scan's echoes in beam order, in the base frame; laser_base: the laser's
// position there; angle_increment_rad: the scan's beam spacing.
std::vector<LandmarkObservation> ExtractLandmarks(const Points2& points_base,
                                                  const Eigen::Vector2d& laser_base,
                                                  double angle_increment_rad,
                                                  const LandmarkExtractionOptions& options);

}  // namespace littermap::reconstruct

#include "reconstruct/landmark_extraction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace littermap::reconstruct {
namespace {

constexpr double kPi = std::numbers::pi;

// Echoes of a laser at the origin, beams every increment_rad from -pi/2 to pi/2, on a circle
// (the part facing the laser) and, optionally, a wall segment; Gaussian range noise.
Points2 ScanOfCircle(const Eigen::Vector2d& centre, double radius_m, double increment_rad,
                     double noise_m, std::mt19937* rng) {
  std::normal_distribution<double> noise(0, noise_m);
  Points2 points;
  for (double a = -kPi / 2; a <= kPi / 2; a += increment_rad) {
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    // Ray-circle intersection: |t d - c|^2 = r^2.
    const double b = d.dot(centre);
    const double disc = b * b - centre.squaredNorm() + radius_m * radius_m;
    if (disc < 0) continue;
    const double t = b - std::sqrt(disc);
    points.push_back((t + noise(*rng)) * d);
  }
  return points;
}

TEST(FitCircleTest, RecoversAnalyticArcsUnderNoise) {
  // Arcs of 60 to 180 degrees, radius 0.1 to 0.5 m, 1 cm noise: centre within a few cm.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.01);
  for (const double radius : {0.1, 0.25, 0.5}) {
    for (const double span_deg : {60.0, 120.0, 180.0}) {
      const Eigen::Vector2d centre(5, -2);
      Points2 arc;
      const double span = span_deg * kPi / 180;
      // Arcs that bulge less than three noise sigmas are not fitted (min_sagitta_rms): there the
      // fit is too non-linear for its covariance to mean anything.
      if (radius * (1 - std::cos(span / 2)) < 3 * 0.01) continue;
      const int n = 25;
      for (int i = 0; i < n; ++i) {
        const double a = kPi - span / 2 + span * i / (n - 1);  // the side facing the origin
        arc.push_back(centre + (radius + noise(rng)) * Eigen::Vector2d(std::cos(a), std::sin(a)));
      }
      const CircleFit fit = FitCircle(arc);
      ASSERT_TRUE(fit.ok) << radius << " " << span_deg;
      // The error lies within the fit's own covariance, sigma^2 (J^T J)^-1 (chi-squared with
      // three degrees of freedom, 99.9 %): short arcs leave the radius and the centre along the
      // arc's axis loose, and the fit says so.
      const Eigen::Vector3d error(fit.centre.x() - centre.x(), fit.centre.y() - centre.y(),
                                  fit.radius_m - radius);
      const Eigen::Matrix3d information =
          fit.normal_matrix / (fit.rms_residual_m * fit.rms_residual_m);
      EXPECT_LT(error.dot(information * error), 16.27) << radius << " " << span_deg;
      if (span_deg >= 180 && radius >= 0.25) {
        EXPECT_LT(error.norm(), 0.015) << radius << " " << span_deg;
      }
      EXPECT_LT(error.norm(), 0.1) << radius << " " << span_deg;
      EXPECT_NEAR(fit.rms_residual_m, 0.01, 0.005);
    }
  }
}

TEST(FitCircleTest, ExactPointsGiveTheExactCircle) {
  Points2 points;
  for (int i = 0; i < 8; ++i) {
    const double a = 0.3 * i;
    points.push_back(Eigen::Vector2d(-3, 40) + 0.3 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  const CircleFit fit = FitCircle(points);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(fit.centre.x(), -3, 1e-9);
  EXPECT_NEAR(fit.centre.y(), 40, 1e-9);
  EXPECT_NEAR(fit.radius_m, 0.3, 1e-9);
}

TEST(FitCircleTest, CollinearPointsHaveNoCircle) {
  Points2 points;
  for (int i = 0; i < 10; ++i) points.push_back({1.0 * i, 2.0 * i});
  EXPECT_FALSE(FitCircle(points).ok);
}

TEST(ExtractLandmarksTest, FindsTrunksAtTheirCentresAndSkipsWalls) {
  std::mt19937 rng(3);
  const double increment = 0.25 * kPi / 180;  // a UTM-30LX
  const Eigen::Vector2d a(6, 2), b(10, -3);
  Points2 scan = ScanOfCircle(a, 0.3, increment, 0.01, &rng);
  const Points2 other = ScanOfCircle(b, 0.15, increment, 0.01, &rng);
  // Merge in beam order (by angle), then a straight wall far to the left.
  scan.insert(scan.end(), other.begin(), other.end());
  std::sort(scan.begin(), scan.end(), [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return std::atan2(p.y(), p.x()) < std::atan2(q.y(), q.x());
  });
  for (double x = -2; x <= 8; x += 0.05) scan.push_back({x, 9.0});
  const std::vector<LandmarkObservation> found =
      ExtractLandmarks(scan, Eigen::Vector2d::Zero(), increment, LandmarkExtractionOptions{});
  ASSERT_EQ(found.size(), 2U);
  const auto near = [&](const Eigen::Vector2d& c, double r) {
    for (const LandmarkObservation& o : found) {
      if ((o.centre_base - c).norm() < 0.05 && std::abs(o.radius_m - r) < 0.05) {
        // The covariance covers the error it reports.
        EXPECT_LT(o.covariance_base.trace(), 0.01);
        EXPECT_GT(o.covariance_base.trace(), 0);
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(near(a, 0.3));
  EXPECT_TRUE(near(b, 0.15));
}

TEST(ExtractLandmarksTest, TheCentreIsTheSameFromOppositeSides) {
  // The reason for landmarks: a trunk seen from the other side gives the same centre.
  std::mt19937 rng(5);
  const double increment = 0.25 * kPi / 180;
  const Eigen::Vector2d trunk(5, 0);
  const Points2 from_west = ScanOfCircle(trunk, 0.25, increment, 0.01, &rng);
  // From (10, 0) looking west: the same scan rotated by pi about the trunk.
  Points2 east_local = ScanOfCircle(trunk, 0.25, increment, 0.01, &rng);
  const auto west = ExtractLandmarks(from_west, Eigen::Vector2d::Zero(), increment, {});
  const auto east = ExtractLandmarks(east_local, Eigen::Vector2d::Zero(), increment, {});
  ASSERT_EQ(west.size(), 1U);
  ASSERT_EQ(east.size(), 1U);
  // East scan in the world: laser at (10, 0) facing -x: world = (10 - x, -y).
  const Eigen::Vector2d east_world(10 - east[0].centre_base.x(), -east[0].centre_base.y());
  EXPECT_LT((west[0].centre_base - east_world).norm(), 0.03);
  // The echoes themselves are about a diameter apart: a matcher overlaying them would be off.
  double west_x = 0, east_x = 0;
  for (const Eigen::Vector2d& p : from_west)
    west_x += p.x() / static_cast<double>(from_west.size());
  for (const Eigen::Vector2d& p : east_local) {
    east_x += (10 - p.x()) / static_cast<double>(east_local.size());
  }
  EXPECT_GT(east_x - west_x, 0.3);
}

TEST(ExtractLandmarksTest, CornersAndShortSegmentsAreNotLandmarks) {
  const double increment = 0.25 * kPi / 180;
  Points2 corner;  // the inside of a corner, in beam order: x = 4 upwards, then y = 4 leftwards
  for (double y = 0; y < 4; y += 0.02) corner.push_back({4, y});
  for (double x = 4; x >= 0; x -= 0.02) corner.push_back({x, 4});
  EXPECT_TRUE(ExtractLandmarks(corner, Eigen::Vector2d::Zero(), increment, {}).empty());
  const Points2 few = {{3, 0}, {3.01, 0.02}, {3.0, 0.04}};
  EXPECT_TRUE(ExtractLandmarks(few, Eigen::Vector2d::Zero(), increment, {}).empty());
}

}  // namespace
}  // namespace littermap::reconstruct

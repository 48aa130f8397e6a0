// Hu-moment shapes (thesis 3.2): analytic values of a rectangle and a circle, invariance to
// rotation, scale and translation of drawn shapes, and both distances.
//
// Tolerances come from rasterisation: a filled 200 x 100 px rectangle rotated by 0..60 degrees
// measured I1 within 1 % and I2 within 6 % of the axis-aligned values (OpenCV 4.6), hence 2 % and
// 10 %; ellipses vary less.

#include "detect/hu_shape.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr int kCanvas = 500;

cv::Mat Rectangle(double width, double height, double angle_deg, cv::Point2f centre = {250, 250}) {
  cv::Mat mask = cv::Mat::zeros(kCanvas, kCanvas, CV_8U);
  cv::Point2f corners[4];
  cv::RotatedRect(centre, cv::Size2f(float(width), float(height)), float(angle_deg))
      .points(corners);
  std::vector<cv::Point> polygon;
  for (const cv::Point2f& p : corners) polygon.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillConvexPoly(mask, polygon, 255);
  return mask;
}

cv::Mat Ellipse(double width, double height, double angle_deg) {
  cv::Mat mask = cv::Mat::zeros(kCanvas, kCanvas, CV_8U);
  cv::ellipse(
      mask, cv::RotatedRect({250, 250}, cv::Size2f(float(width), float(height)), float(angle_deg)),
      255, cv::FILLED);
  return mask;
}

void ExpectSameShape(const HuShape& reference, const HuShape& other, const char* what) {
  EXPECT_NEAR(other.values[0], reference.values[0], 0.02 * reference.values[0]) << what;
  EXPECT_NEAR(other.values[1], reference.values[1], 0.10 * reference.values[1]) << what;
  const HuDistanceOptions options;
  for (std::size_t i = 2; i < other.values.size(); ++i) {
    // Centrally symmetric: the third-order invariants are zero up to rasterisation noise.
    EXPECT_LT(std::abs(other.values[i]), options.zero_threshold) << what << " value " << i;
  }
}

TEST(HuShape, AxisAlignedRectangleAndCircleMatchTheirAnalyticInvariants) {
  cv::Mat rectangle = cv::Mat::zeros(kCanvas, kCanvas, CV_8U);
  rectangle(cv::Rect(100, 150, 200, 100)).setTo(255);
  const HuShape r = ComputeHuShape(rectangle);
  // w x h rectangle: eta20 = w / (12 h), eta02 = h / (12 w); I1 = their sum, I2 = difference^2.
  EXPECT_NEAR(r.values[0], (2.0 + 0.5) / 12, 1e-4);
  EXPECT_NEAR(r.values[1], std::pow((2.0 - 0.5) / 12, 2), 1e-4);
  EXPECT_EQ(r.area_px, 20000);
  const HuShape circle = ComputeHuShape(Ellipse(200, 200, 0));
  EXPECT_NEAR(circle.values[0], 1.0 / (2 * std::numbers::pi), 1e-4);  // I1 of a disc
  EXPECT_LT(circle.values[1], 1e-6);
}

TEST(HuShape, RectangleIsInvariantToRotationScaleAndTranslation) {
  const HuShape reference = ComputeHuShape(Rectangle(200, 100, 0));
  for (double angle : {15.0, 30.0, 45.0, 60.0}) {
    ExpectSameShape(reference, ComputeHuShape(Rectangle(200, 100, angle)), "rotated");
  }
  ExpectSameShape(reference, ComputeHuShape(Rectangle(300, 150, 20)), "scaled 1.5 and rotated");
  ExpectSameShape(reference, ComputeHuShape(Rectangle(100, 50, 0)), "scaled 0.5");
  const HuShape moved = ComputeHuShape(Rectangle(200, 100, 0, {150, 300}));
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(moved.values[i], reference.values[i], 1e-12) << "translation is exact";
  }
}

TEST(HuShape, EllipseIsInvariantToRotationAndScale) {
  const HuShape reference = ComputeHuShape(Ellipse(240, 120, 0));
  for (double angle : {20.0, 45.0, 80.0}) {
    ExpectSameShape(reference, ComputeHuShape(Ellipse(240, 120, angle)), "rotated");
  }
  ExpectSameShape(reference, ComputeHuShape(Ellipse(120, 60, 33)), "scaled 0.5 and rotated");
}

TEST(HuShape, RectanglesAreCloserToRectanglesThanToCircles) {
  const HuShape rectangle = ComputeHuShape(Rectangle(200, 100, 0));
  const HuShape other_rectangle = ComputeHuShape(Rectangle(300, 150, 35));
  const HuShape circle = ComputeHuShape(Ellipse(180, 180, 0));
  EXPECT_LT(HuInverseDistance(rectangle, other_rectangle), HuInverseDistance(rectangle, circle));
  EXPECT_LT(HuLogDistance(rectangle, other_rectangle), HuLogDistance(rectangle, circle));
  EXPECT_EQ(HuInverseDistance(rectangle, rectangle), 0.0);
  EXPECT_EQ(HuLogDistance(rectangle, rectangle), 0.0);
  EXPECT_EQ(HuInverseDistance(rectangle, circle), HuInverseDistance(circle, rectangle));
  EXPECT_EQ(HuLogDistance(rectangle, circle), HuLogDistance(circle, rectangle));
}

TEST(HuShape, DistancesTreatInvariantsBelowTheThresholdAsZero) {
  HuShape a, b;
  a.values = {0.2, 0.01, 1e-9, -1e-12, 0, 0};
  b.values = {0.25, 0, -1e-10, 0, 0, 0};
  HuDistanceOptions options;
  options.zero_threshold = 1e-6;
  // I1: |1/0.2 - 1/0.25| = 1; I2: 0.01 against zero -> |100 - 1e6|; the rest are all zero.
  EXPECT_NEAR(HuInverseDistance(a, b, options), 1.0 + (1e6 - 100), 1e-6);
  // Signed logs: log10(1 + m / 1e-6) per value; the noise terms are below 1e-3 each.
  const double expected = std::log10(1 + 0.25e6) - std::log10(1 + 0.2e6) + std::log10(1 + 1e4);
  EXPECT_NEAR(HuLogDistance(a, b, options), expected, 2e-3);
  options.zero_threshold = 0;
  EXPECT_THROW(HuInverseDistance(a, b, options), UsageError);
  EXPECT_THROW(HuLogDistance(a, b, options), UsageError);
}

TEST(HuShape, RejectsEmptyAndWrongMasks) {
  EXPECT_THROW(ComputeHuShape(cv::Mat::zeros(10, 10, CV_8U)), UsageError);
  EXPECT_THROW(ComputeHuShape(cv::Mat::ones(10, 10, CV_32F)), UsageError);
  EXPECT_THROW(ComputeHuShape(cv::Mat()), UsageError);
}

}  // namespace
}  // namespace littermap::detect

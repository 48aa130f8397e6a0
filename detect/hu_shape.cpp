#include "detect/hu_shape.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

// cv::HuMoments indices kept: all but the third (index 2).
constexpr std::array<int, kHuShapeValueCount> kKept = {0, 1, 3, 4, 5, 6};

// 1 / m with |m| < threshold taken as +threshold (see the header).
double Reciprocal(double m, double threshold) {
  return std::abs(m) < threshold ? 1.0 / threshold : 1.0 / m;
}

double SignedLog(double m, double threshold) {
  const double magnitude = std::log10(1.0 + std::abs(m) / threshold);
  return m < 0 ? -magnitude : magnitude;
}

}  // namespace

HuShape ComputeHuShape(const cv::Mat& mask) {
  if (mask.empty() || mask.type() != CV_8UC1) {
    throw UsageError("Hu shape: mask must be a non-empty CV_8UC1 image");
  }
  const cv::Moments moments = cv::moments(mask, /*binaryImage=*/true);
  if (!(moments.m00 > 0)) throw UsageError("Hu shape: the mask has no object pixel");
  double hu[7];
  cv::HuMoments(moments, hu);
  HuShape shape;
  for (std::size_t i = 0; i < kKept.size(); ++i) shape.values[i] = hu[kKept[i]];
  shape.area_px = moments.m00;
  return shape;
}

void HuDistanceOptions::Validate() const {
  if (!(zero_threshold > 0) || !std::isfinite(zero_threshold)) {
    throw UsageError("Hu shape distance: zero_threshold must be > 0 and finite");
  }
}

double HuInverseDistance(const HuShape& a, const HuShape& b, const HuDistanceOptions& options) {
  options.Validate();
  double distance = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    distance += std::abs(Reciprocal(a.values[i], options.zero_threshold) -
                         Reciprocal(b.values[i], options.zero_threshold));
  }
  return distance;
}

double HuLogDistance(const HuShape& a, const HuShape& b, const HuDistanceOptions& options) {
  options.Validate();
  double distance = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    distance += std::abs(SignedLog(a.values[i], options.zero_threshold) -
                         SignedLog(b.values[i], options.zero_threshold));
  }
  return distance;
}

}  // namespace littermap::detect

#include "detect/object_features.hpp"

#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "detect/hu_shape.hpp"

namespace littermap::detect {
namespace {

void AppendColourStatistics(const cv::Mat& colour_bgr, const cv::Mat& mask,
                            std::vector<float>* raw) {
  cv::Mat scaled, hsv;
  colour_bgr.convertTo(scaled, CV_32FC3, 1.0 / 255.0);
  cv::cvtColor(scaled, hsv, cv::COLOR_BGR2HSV);
  double cx = 0, cy = 0, s_sum = 0, v_sum = 0, v_squares = 0;
  int n = 0;
  for (int v = 0; v < hsv.rows; ++v) {
    for (int u = 0; u < hsv.cols; ++u) {
      if (!mask.at<std::uint8_t>(v, u)) continue;
      const cv::Vec3f p = hsv.at<cv::Vec3f>(v, u);
      const double h = p[0] * std::numbers::pi / 180.0;
      cx += p[1] * std::cos(h);
      cy += p[1] * std::sin(h);
      s_sum += p[1];
      v_sum += p[2];
      v_squares += p[2] * p[2];
      ++n;
    }
  }
  const double mean_v = v_sum / n;
  raw->push_back(static_cast<float>(cx / n));
  raw->push_back(static_cast<float>(cy / n));
  raw->push_back(static_cast<float>(s_sum / n));
  raw->push_back(static_cast<float>(mean_v));
  raw->push_back(static_cast<float>(std::sqrt(std::max(0.0, v_squares / n - mean_v * mean_v))));
}

}  // namespace

ObjectDescription DescribeObject(const ObjectSample& object) {
  ObjectDescription d;
  d.histogram = ComputeColourHistogram(object.colour_bgr, object.mask);
  d.hu = ComputeHuShape(object.mask);
  d.raw.reserve(kRawFeatureCount);
  const ColourHistogram shares = d.histogram.Normalised();
  for (double share : shares.counts) d.raw.push_back(static_cast<float>(share));
  AppendColourStatistics(object.colour_bgr, object.mask, &d.raw);
  const double pixels = cv::countNonZero(object.mask);
  d.raw.push_back(static_cast<float>(pixels / static_cast<double>(object.mask.total())));
  d.raw.push_back(static_cast<float>(double(object.mask.cols) / object.mask.rows));
  d.raw.push_back(static_cast<float>(object.size_m));
  d.raw.push_back(static_cast<float>(object.width_m));
  d.raw.push_back(static_cast<float>(object.height_m));
  d.raw.push_back(static_cast<float>(object.height_m / std::max(0.01, object.size_m)));
  for (double m : d.hu.values) {
    // sign(m) log|m|, as OpenCV's matchShapes scales them: the raw moments span decades.
    d.raw.push_back(static_cast<float>(m == 0 ? 0.0 : std::copysign(std::log10(std::abs(m)), m)));
  }
  return d;
}

}  // namespace littermap::detect

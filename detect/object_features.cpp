#include "detect/object_features.hpp"

#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "detect/hu_shape.hpp"

namespace littermap::detect {
namespace {

// Mean chroma (s cos h, s sin h), mean and spread of S and V, and the mean gradient magnitude
// of the brightness (texture: bark, petals and gravel are busy; cans and cartons are smooth).
void AppendColourStatistics(const cv::Mat& colour_bgr, const cv::Mat& mask,
                            std::vector<float>* raw) {
  cv::Mat scaled, hsv, grey, dx, dy;
  colour_bgr.convertTo(scaled, CV_32FC3, 1.0 / 255.0);
  cv::cvtColor(scaled, hsv, cv::COLOR_BGR2HSV);
  cv::cvtColor(scaled, grey, cv::COLOR_BGR2GRAY);
  cv::Sobel(grey, dx, CV_32F, 1, 0);
  cv::Sobel(grey, dy, CV_32F, 0, 1);
  double cx = 0, cy = 0, s_sum = 0, s_squares = 0, v_sum = 0, v_squares = 0, gradient = 0;
  int n = 0;
  for (int v = 0; v < hsv.rows; ++v) {
    for (int u = 0; u < hsv.cols; ++u) {
      if (!mask.at<std::uint8_t>(v, u)) continue;
      const cv::Vec3f p = hsv.at<cv::Vec3f>(v, u);
      const double h = p[0] * std::numbers::pi / 180.0;
      cx += p[1] * std::cos(h);
      cy += p[1] * std::sin(h);
      s_sum += p[1];
      s_squares += p[1] * p[1];
      v_sum += p[2];
      v_squares += p[2] * p[2];
      gradient += std::hypot(dx.at<float>(v, u), dy.at<float>(v, u));
      ++n;
    }
  }
  const double mean_s = s_sum / n, mean_v = v_sum / n;
  for (const double value :
       {cx / n, cy / n, mean_s, mean_v, std::sqrt(std::max(0.0, s_squares / n - mean_s * mean_s)),
        std::sqrt(std::max(0.0, v_squares / n - mean_v * mean_v)), gradient / n}) {
    raw->push_back(static_cast<float>(value));
  }
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

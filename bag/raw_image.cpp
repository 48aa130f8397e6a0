#include "bag/raw_image.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

// The image's pixels in place (no copy), after checking the buffer holds them.
cv::Mat View(const msg::Image& image, int type, const char* kind) {
  const std::size_t row_bytes = std::size_t{image.width} * CV_ELEM_SIZE(type);
  if (image.width == 0 || image.height == 0 || image.step < row_bytes ||
      image.data.size() < std::size_t{image.step} * image.height) {
    throw BadInputError(std::string(kind) + " image (" + image.encoding + ", " +
                        std::to_string(image.width) + "x" + std::to_string(image.height) +
                        ", step " + std::to_string(image.step) + ") holds " +
                        std::to_string(image.data.size()) + " bytes, too few");
  }
  return cv::Mat(static_cast<int>(image.height), static_cast<int>(image.width), type,
                 const_cast<std::uint8_t*>(image.data.data()), image.step);
}

}  // namespace

cv::Mat DecodeRawColor(const msg::Image& image) {
  const std::string& encoding = image.encoding;
  cv::Mat bgr;
  if (encoding == "bgr8") {
    bgr = View(image, CV_8UC3, "colour").clone();
  } else if (encoding == "rgb8") {
    cv::cvtColor(View(image, CV_8UC3, "colour"), bgr, cv::COLOR_RGB2BGR);
  } else if (encoding == "bgra8") {
    cv::cvtColor(View(image, CV_8UC4, "colour"), bgr, cv::COLOR_BGRA2BGR);
  } else if (encoding == "rgba8") {
    cv::cvtColor(View(image, CV_8UC4, "colour"), bgr, cv::COLOR_RGBA2BGR);
  } else if (encoding == "mono8" || encoding == "8UC1") {
    cv::cvtColor(View(image, CV_8UC1, "colour"), bgr, cv::COLOR_GRAY2BGR);
  } else {
    throw BadInputError("colour image encoding '" + encoding +
                        "' is not supported (bgr8, rgb8, bgra8, rgba8, mono8)");
  }
  return bgr;
}

cv::Mat DecodeRawDepthMm(const msg::Image& image) {
  const std::string& encoding = image.encoding;
  if (encoding == "16UC1" || encoding == "mono16") {
    cv::Mat depth = View(image, CV_16UC1, "depth").clone();
    if (image.is_bigendian) {
      depth.forEach<std::uint16_t>(
          [](std::uint16_t& v, const int*) { v = static_cast<std::uint16_t>(v << 8 | v >> 8); });
    }
    return depth;
  }
  if (encoding != "32FC1") {
    throw BadInputError("depth image encoding '" + encoding +
                        "' is not supported (16UC1 or mono16 in millimetres, 32FC1 in metres)");
  }
  const cv::Mat metres = View(image, CV_32FC1, "depth");
  cv::Mat depth(metres.size(), CV_16UC1);
  for (int v = 0; v < metres.rows; ++v) {
    const auto* in = metres.ptr<std::uint8_t>(v);
    auto* out = depth.ptr<std::uint16_t>(v);
    for (int u = 0; u < metres.cols; ++u) {
      std::uint8_t bytes[4];
      for (int b = 0; b < 4; ++b) bytes[b] = in[4 * u + (image.is_bigendian ? 3 - b : b)];
      float m;
      std::memcpy(&m, bytes, sizeof(m));
      const float mm = std::round(m * 1000.0f);
      out[u] = std::isfinite(mm) && mm > 0 && mm <= 65535.0f ? static_cast<std::uint16_t>(mm) : 0;
    }
  }
  return depth;
}

}  // namespace littermap::bag

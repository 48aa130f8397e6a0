#include "bag/rgbd_pairing.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "core/error.hpp"

namespace littermap::bag {

namespace {

cv::Mat DecodedAt(const std::string& origin, cv::Mat (*decode)(const CameraImage&),
                  const CameraImage& image) {
  try {
    return decode(image);
  } catch (const BadInputError& error) {
    if (origin.empty()) throw;
    throw BadInputError(origin + ": " + error.what());
  }
}

}  // namespace

cv::Mat DecodeColor(const CompressedRgbd& frame) {
  return DecodedAt(frame.colour_origin, &DecodeColor, frame.colour);
}

cv::Mat DecodeDepthMm(const CompressedRgbd& frame) {
  return DecodedAt(frame.depth_origin, &DecodeDepthMm, frame.depth);
}

RgbdPairing::RgbdPairing(double max_gap_s)
    : max_gap_ns_(static_cast<TimestampNs>(std::llround(max_gap_s * 1e9))) {}

std::optional<CompressedRgbd> RgbdPairing::AddColour(CameraImage image, std::string origin) {
  colour_ = std::move(image);
  colour_origin_ = std::move(origin);
  return Pair();
}

std::optional<CompressedRgbd> RgbdPairing::AddDepth(CameraImage image, std::string origin) {
  depth_ = std::move(image);
  depth_origin_ = std::move(origin);
  return Pair();
}

void RgbdPairing::Reset() {
  colour_.reset();
  depth_.reset();
}

std::optional<CompressedRgbd> RgbdPairing::Pair() {
  if (!colour_ || !depth_) return std::nullopt;
  const TimestampNs stamp_ns = StampOf(*colour_);
  if (std::llabs(stamp_ns - StampOf(*depth_)) > max_gap_ns_) return std::nullopt;
  CompressedRgbd frame{stamp_ns, std::move(*colour_), std::move(*depth_), std::move(colour_origin_),
                       std::move(depth_origin_)};
  Reset();
  return frame;
}

}  // namespace littermap::bag

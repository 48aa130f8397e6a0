#include "bag/rgbd_pairing.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

namespace littermap::bag {

RgbdPairing::RgbdPairing(double max_gap_s)
    : max_gap_ns_(static_cast<TimestampNs>(std::llround(max_gap_s * 1e9))) {}

std::optional<CompressedRgbd> RgbdPairing::AddColour(CameraImage image) {
  colour_ = std::move(image);
  return Pair();
}

std::optional<CompressedRgbd> RgbdPairing::AddDepth(CameraImage image) {
  depth_ = std::move(image);
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
  CompressedRgbd frame{stamp_ns, std::move(*colour_), std::move(*depth_)};
  Reset();
  return frame;
}

}  // namespace littermap::bag

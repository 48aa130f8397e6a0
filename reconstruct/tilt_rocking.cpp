#include "reconstruct/tilt_rocking.hpp"

#include <algorithm>
#include <vector>

namespace littermap::reconstruct {
namespace {

double Median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

void TiltRocking::Add(TimestampNs stamp_ns, const Tilt& tilt) {
  samples_.push_back({stamp_ns, tilt});
  const auto window_ns = static_cast<TimestampNs>(window_s_ * 1e9);
  while (samples_.front().stamp_ns < stamp_ns - window_ns) samples_.pop_front();
}

double TiltRocking::LatestRockingRad() const {
  if (samples_.empty()) return 0;
  const Tilt& tilt = samples_.back().tilt;
  std::vector<double> roll_rad, pitch_rad;
  roll_rad.reserve(samples_.size());
  pitch_rad.reserve(samples_.size());
  for (const Sample& s : samples_) {
    roll_rad.push_back(s.tilt.roll_rad);
    pitch_rad.push_back(s.tilt.pitch_rad);
  }
  return TiltAngle(
      {tilt.roll_rad - Median(std::move(roll_rad)), tilt.pitch_rad - Median(std::move(pitch_rad))});
}

}  // namespace littermap::reconstruct

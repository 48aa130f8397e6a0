#include "reconstruct/keyframe_buffer.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace littermap::reconstruct {

void KeyFrameBufferOptions::Validate() const {
  if (!(translation_threshold_m > 0) || !(rotation_threshold_rad > 0)) {
    throw UsageError("key-frame buffer: thresholds must be > 0");
  }
  if (capacity < 1) throw UsageError("key-frame buffer: capacity must be >= 1");
}

KeyFrameBuffer::KeyFrameBuffer(const KeyFrameBufferOptions& options) : options_(options) {
  options_.Validate();
}

bool KeyFrameBuffer::NeedsFrame(const PlanarPose& T_world_base) const {
  if (frames_.empty()) return true;
  const PlanarPose moved = Between(frames_.back().T_world_base, T_world_base);
  return std::hypot(moved.x_m, moved.y_m) > options_.translation_threshold_m ||
         std::abs(moved.theta_rad) > options_.rotation_threshold_rad;
}

void KeyFrameBuffer::Add(BufferedFrame frame) {
  frames_.push_back(std::move(frame));
  while (frames_.size() > options_.capacity) frames_.pop_front();
}

const BufferedFrame* KeyFrameBuffer::Nearest(const PlanarPose& T_world_base) const {
  const BufferedFrame* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const BufferedFrame& frame : frames_) {
    const PlanarPose d = Between(frame.T_world_base, T_world_base);
    const double distance = std::hypot(d.x_m, d.y_m) + std::abs(d.theta_rad);
    if (distance < best_distance) {
      best_distance = distance;
      best = &frame;
    }
  }
  return best;
}

void KeyFrameBuffer::Correct(const PlanarPose& T_new_old) {
  for (BufferedFrame& frame : frames_) frame.T_world_base = Compose(T_new_old, frame.T_world_base);
}

}  // namespace littermap::reconstruct

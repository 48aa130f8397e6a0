#pragma once
// The key-frame buffer of thesis 2.5 (routine 2): scans buffered at smaller pose changes than
// the top map's key frames. When matching against the top map fails (e.g. a door passed and the
// scene changed), the scan is matched against the buffered frame nearest to its predicted pose,
// which looks much more like it than the older top map does.

#include <cstddef>
#include <deque>

#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct KeyFrameBufferOptions {
  double translation_threshold_m = 0.1;
  double rotation_threshold_rad = 0.08;
  std::size_t capacity = 20;
  void Validate() const;
};

struct BufferedFrame {
  PlanarPose T_world_base;
  Points2 points_base;
};

class KeyFrameBuffer {
 public:
  explicit KeyFrameBuffer(const KeyFrameBufferOptions& options);

  bool NeedsFrame(const PlanarPose& T_world_base) const;
  void Add(BufferedFrame frame);  // drops the oldest beyond capacity
  // The buffered frame closest to the pose (translation plus 1 m per radian), or null.
  const BufferedFrame* Nearest(const PlanarPose& T_world_base) const;
  // Moves every buffered pose by T_new_old (after a pose-graph correction).
  void Correct(const PlanarPose& T_new_old);
  std::size_t size() const { return frames_.size(); }

 private:
  KeyFrameBufferOptions options_;
  std::deque<BufferedFrame> frames_;
};

}  // namespace littermap::reconstruct

#pragma once
// Camera frames wait for the odometry reading after them, as scans do, so that the odometry pose
// a frame is given is interpolated at its stamp. The odometry carries the camera's pose between
// the frame and the scans; the last reading before a frame is up to one reading's period old,
// and turning at 1 rad/s, 20 ms is more than a degree: the camera's loops and placements were
// off by that much in every turn.

#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "bag/rgbd_pairing.hpp"
#include "core/planar_pose.hpp"
#include "reconstruct/odometry_history.hpp"

namespace littermap::reconstruct {

struct OdometryFrame {
  bag::CompressedRgbd frame;
  std::optional<PlanarPose> T_odom_base;  // at the frame's stamp, if the odometry has it
};

class FrameQueue {
 public:
  void Push(bag::CompressedRgbd frame) { frames_.push_back(std::move(frame)); }
  // The frames, oldest first, whose stamps the odometry covers, and every frame up to until_ns
  // whatever the odometry (a scan after them is about to be tracked), each with the odometry at
  // its stamp.
  std::vector<OdometryFrame> TakeReady(const OdometryHistory& odometry,
                                       std::optional<TimestampNs> until_ns = std::nullopt);
  std::size_t waiting() const { return frames_.size(); }

 private:
  std::deque<bag::CompressedRgbd> frames_;
};

}  // namespace littermap::reconstruct

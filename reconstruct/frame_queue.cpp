#include "reconstruct/frame_queue.hpp"

namespace littermap::reconstruct {

std::vector<OdometryFrame> FrameQueue::TakeReady(const OdometryHistory& odometry,
                                                 std::optional<TimestampNs> until_ns) {
  std::vector<OdometryFrame> ready;
  while (!frames_.empty() && (odometry.Covers(frames_.front().stamp_ns) ||
                              (until_ns && frames_.front().stamp_ns <= *until_ns))) {
    const auto at = odometry.At(frames_.front().stamp_ns);
    ready.push_back(
        {std::move(frames_.front()), at ? std::optional(at->T_odom_base) : std::nullopt});
    frames_.pop_front();
  }
  return ready;
}

}  // namespace littermap::reconstruct

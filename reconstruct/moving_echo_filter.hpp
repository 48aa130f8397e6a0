#pragma once
// Echoes that move with the robot are not the world. Where a hill rises ahead, or the robot
// pitches in a dip, the scan plane cuts the ground along a long arc that follows the robot: ICP
// locks onto it, and the pose sticks or turns with it. The tilt alone cannot predict these arcs
// (ScanToPoints drops only the ground under a tilted scanner), but the odometry can expose them:
// brought into the frames of earlier scans (a quarter of a second and a second older) by the
// odometry between them, a static echo lands on their echoes, a moving arc lands a little beside
// them. Those are dropped; a scan that is mostly such echoes is given up (the laser hits the
// ground: thesis 2.5), so the tracker falls back on its other routines. Over a second wheels
// turned by a gyro are far more precise than the shifts looked for; wheels alone can slip by
// degrees, so without a gyro (and without a tilt: indoors, CARMEN logs) the filter is not used.

#include <cstddef>
#include <deque>
#include <memory>

#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

// kAuto: where the terrain is hilly (TerrainRelief over relief_window_m above min_relief_m).
enum class MovingEchoMode { kAuto, kOn, kOff };

struct MovingEchoFilterOptions {
  // By default the filter runs where the ground under the last 40 m of path rose and fell by
  // more than 0.4 m, about a scanner's height: on the hilly 15-minute park_large survey (relief
  // 0.73 m at the median, over 0.4 m on 97 % of the route) the scan plane cuts the hills, while
  // on the gentle sample park (0.3 m at most) the filter only costs accuracy.
  MovingEchoMode mode = MovingEchoMode::kAuto;
  double min_relief_m = 0.4;
  double relief_window_m = 40;
  double min_interval_s = 0.25;  // the earlier scan compared with is at least this much older
  // Each scan is also compared with one at least this much older (0: not). A ridge beside the
  // path that the robot drives obliquely across is a line of echoes parallel to the path: it
  // slides along itself, where no shift shows, and creeps across by a few centimetres in a
  // quarter of a second, within the tolerance. Over a second it has crept 10-20 cm, and ICP,
  // which pulls the scan onto the line where the map has it, would slide the pose sideways with
  // it (park_large's west valley: 0.46 m across 25 s, with the one-scan comparison alone).
  double long_interval_s = 1.0;
  // A static echo lies within this distance of the earlier scan's (noise, beam spacing at range).
  double static_tolerance_m = 0.06;
  double static_tolerance_per_m = 0.004;
  // Further than this from every earlier echo, an echo is new to the view, not moved.
  double max_shift_m = 0.6;
  // A scan with a larger share of moving echoes is given up.
  double max_moving_fraction = 0.5;
  void Validate() const;
};

struct MovingEchoResult {
  Points2 points_base;     // the static echoes
  std::size_t moving = 0;  // echoes dropped as moving with the robot
  bool given_up = false;   // too many moving echoes: do not match this scan
};

class MovingEchoFilter {
 public:
  explicit MovingEchoFilter(const MovingEchoFilterOptions& options);

  // points_base: the scan's (downsampled) echoes; T_odom_base: the odometry at its stamp.
  // Scans must come in time order; the first ones, with no scan min_interval_s older, pass.
  MovingEchoResult Filter(TimestampNs stamp_ns, const PlanarPose& T_odom_base, Points2 points_base);
  // Keeps a scan for the comparisons of later ones without filtering it (where the terrain does
  // not call for the filter): the same history as Filter, none of the per-echo searches.
  void Remember(TimestampNs stamp_ns, const PlanarPose& T_odom_base, Points2 points_base);

 private:
  struct Earlier {
    TimestampNs stamp_ns = 0;
    PlanarPose T_odom_base;
    Points2 points_base;
    std::shared_ptr<const IcpTarget> echoes;  // KD-tree over the points, built when first needed
  };
  // The newest kept scan at least interval_s older than stamp_ns, if any.
  Earlier* Reference(TimestampNs stamp_ns, double interval_s);
  // Drops the scans no later one will compare with.
  void Forget(TimestampNs stamp_ns);
  // The earlier scan's echoes, their KD-tree built on first use.
  static const IcpTarget& EchoesOf(Earlier& earlier);
  // Whether an echo, brought into an earlier scan's frame (p_earlier), lies beside that scan's
  // echoes: further than the static tolerance from the nearest, closer than max_shift_m.
  bool Beside(const IcpTarget& echoes, const Eigen::Vector2d& p_earlier, double tolerance_sq) const;
  MovingEchoFilterOptions options_;
  std::deque<Earlier> earlier_;
};

}  // namespace littermap::reconstruct

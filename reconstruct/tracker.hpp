#pragma once
// The hybrid tracker of thesis 2.5 (Alg. 2.5.1.1) for one scan at a time:
//   1. match against the top map (GKMap, routine "global") from the predicted pose;
//   2. if the matching ratio is too low, match against the nearest buffered key frame
//      (routine "buffer") and force a key frame so the top map learns the new pattern;
//   3. if that fails too, ask the RGB-D aligner (routine "rgbd", RgbdFallback) for a pose and
//      accept it if a 2D match from it reaches the matching ratio less alpha, or if it agrees
//      with the prediction;
//   otherwise keep the predicted pose (routine "odometry-only").
// The prediction is the odometry increment since the last scan, or a constant-velocity model
// when odometry is missing or faster than its limits; where routine 1 does not confirm the one
// chosen, it tries the other, and the one the laser confirms wins (odometry stalls, slips and
// catches up; closely stamped scans can be far apart). Matches of routines 1 and 2 are fused with
// it, each weighted by its information; routine 3's pose only in heading, and only where a gyro
// turned the odometry (the wheels may have slipped where the laser lost the map).

#include <cstddef>
#include <optional>
#include <string_view>

#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/keyframe_buffer.hpp"
#include "reconstruct/keyframe_map.hpp"

namespace littermap::reconstruct {

enum class Routine { kGlobal, kBuffer, kRgbd, kOdometryOnly };
std::string_view RoutineName(Routine routine);

struct TrackerOptions {
  IcpOptions icp;
  KeyFrameMapOptions key_frames;
  KeyFrameBufferOptions buffer;
  double min_matching_ratio = 0.35;        // routine 1 accepted at or above
  double min_buffer_matching_ratio = 0.4;  // routine 2 accepted at or above
  // Tilted further than this from level (IMU roll and pitch; a root, a kerb, a steep bank), the
  // scan plane sweeps other heights of the scene than the map's and may graze the ground: routines
  // 1 and 2 then need this matching ratio.
  double max_level_tilt_rad = 0.12;
  double tilted_min_matching_ratio = 0.6;
  double rgbd_ratio_slack = 0.1;  // routine 3: the thesis's alpha
  double rgbd_sigma_m = 0.03;     // routine 3's pose, standard deviations
  double rgbd_sigma_rad = 0.02;
  // Odometry moving faster than this between two scans is treated as broken. Steps up to
  // the per-step limits always pass: stamps may be synthesised (dt near 0) or sparse.
  double max_odometry_speed_m_s = 5.0;
  double max_odometry_turn_rate_rad_s = 6.0;
  double max_odometry_step_m = 2.0;
  double max_odometry_step_rad = 1.5;
  double max_scan_gap_s = 1.0;  // a longer gap does not trust the constant-velocity model
  // A match that moves the pose further than this from the prediction slid along a corridor or
  // snapped to the wrong wall: base + fraction of the predicted motion.
  double max_correction_m = 0.3;
  double max_correction_rad = 0.12;
  double max_correction_fraction = 0.25;
  // A match that overlays at least this share of its echoes may correct the heading up to
  // max_large_turn_correction_rad: real odometry glitches by 10-20 degrees in one step.
  double min_ratio_large_turn_correction = 0.9;
  double max_large_turn_correction_rad = 0.4;
  // The laser arbitrates between the odometry and constant velocity only where the matches from
  // both predictions end this close together, or the other's overlays this much more of the scan.
  double max_arbitration_disagreement_m = 0.1;
  double max_arbitration_disagreement_rad = 0.05;
  double min_arbitration_ratio_gain = 0.2;
  // Constant velocity predicts nothing over a longer gap between scans (logs thinned to one scan
  // a metre), so there is nothing to arbitrate.
  double max_arbitration_gap_s = 0.5;
  // The prediction is fused with every accepted match, each weighted by its information, so a
  // scan that constrains the pose only partly (one trunk, one wall) keeps the prediction in the
  // directions it leaves open instead of sliding there. Standard deviations of the prediction:
  // a floor plus a share of the predicted motion; the constant-velocity model is far weaker.
  double odometry_sigma_m = 0.01;
  double odometry_sigma_per_m = 0.05;
  double odometry_sigma_rad = 0.005;
  double odometry_sigma_rad_per_m = 0.02;
  double odometry_sigma_rad_per_rad = 0.05;
  double constant_velocity_sigma_factor = 10;
  // The heading of odometry turned by a gyro (GyroOdometry) drifts with time, not distance, and
  // far less: standard deviations of its heading, a floor plus drift and scale error.
  double gyro_sigma_rad = 0.001;
  double gyro_sigma_rad_per_s = 0.0006;
  double gyro_sigma_rad_per_rad = 0.002;
  // With a gyro, a pose whose heading is further from the gyro's since the anchor than this
  // chi-squared (one degree of freedom, 99.9 %) allows is not taken from a match or the camera.
  // The variance is the gyro's plus the match's floor: against a gyro's heading a match's
  // covariance gets this floor (its Gauss-Newton information sees neither correlated echoes nor
  // the map's error).
  double max_gyro_chi2 = 10.83;
  // With a gyro, a match whose position is further from the odometry's since the anchor than this
  // chi-squared (two degrees of freedom, 99.9 %) allows, with the odometry model's covariance
  // over that motion plus the match's floor, is not taken: the laser slid (ground echoes that
  // move with the robot, a row of trunks) where the wheels did not.
  double max_odometry_chi2 = 13.82;
  double match_sigma_floor_m = 0.005;
  double match_sigma_floor_rad = 0.005;
  void Validate() const;
};

struct TrackInput {
  TimestampNs stamp_ns = 0;
  Points2 points_base;                    // downsampled scan points, at least a few
  std::optional<PlanarPose> T_odom_base;  // odometry at the scan's time, if any
  std::optional<Tilt> tilt;               // roll and pitch of the base (IMU), if known
  bool heading_from_gyro = false;         // the odometry's turn since the last scan is a gyro's
};

struct TrackStep {
  std::size_t scan_index = 0;
  Routine routine = Routine::kOdometryOnly;
  PlanarPose T_world_base;
  double matching_ratio = 0;
  bool odometry_used = false;  // false: constant-velocity prediction
  bool new_key_frame = false;
  std::size_t key_frame = 0;  // the key frame this scan's pose is anchored to
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
};

// Routine 3: a pose for a scan the laser could not place, from the RGB-D aligner (thesis 2.4,
// reconstruct/rgbd_tracker.hpp), and the outcome of every scan (to take RGB-D key frames).
// A camera frame that matched an RGB-D key frame from much earlier on the path: a loop.
struct CameraLoop {
  std::size_t key_frame = 0;  // the 2D key frame the old RGB-D key frame hangs on
  PlanarPose T_world_base;    // the base pose at the scan, as the alignment puts it
  double confidence = 0;      // RgbdAlignment::confidence
};

class RgbdFallback {
 public:
  virtual ~RgbdFallback() = default;
  virtual std::optional<PlanarPose> AlignAt(const TrackInput& input,
                                            const PlanarPose& T_world_base_predicted,
                                            const KeyFrameMap& map) = 0;
  virtual void OnTracked(const TrackInput& input, const TrackStep& step,
                         const KeyFrameMap& map) = 0;
  // After a scan made a key frame: a loop from the camera frame at its time to an RGB-D key frame
  // taken long before, if one matches (none by default).
  virtual std::optional<CameraLoop> FindLoop(const TrackInput& input, const TrackStep& step,
                                             const KeyFrameMap& map) {
    (void)input, (void)step, (void)map;
    return std::nullopt;
  }
};

// How a pose was predicted: odometry (its heading from the gyro or not) or constant velocity.
enum class Prediction { kOdometry, kGyroOdometry, kConstantVelocity };
// The prediction of a step that used the odometry or not (then constant velocity), its heading
// turned by the gyro or not.
Prediction PredictionOf(bool odometry_used, bool heading_from_gyro);
// Information (x, y, theta) of a pose predicted `motion` away from a known one, elapsed_s later,
// by the model of the tracker's options.
Eigen::Matrix3d PredictionInformation(const TrackerOptions& options, const PlanarPose& motion,
                                      double elapsed_s, Prediction prediction);

class Tracker {
 public:
  Tracker(const TrackerOptions& options, KeyFrameMap* map, RgbdFallback* rgbd = nullptr);

  TrackStep Track(std::size_t scan_index, const TrackInput& input);
  // After the pose graph moved the key frames: re-anchor the current pose and the buffer.
  void OnKeyFramesMoved(const PlanarPose& T_new_old_last_key_frame);
  // Scans whose odometry step was not used: beyond the speed limits, or overruled by the laser.
  std::size_t odometry_rejected() const { return odometry_rejected_; }
  // Scans where the laser chose between the odometry and the constant-velocity model because it
  // did not confirm the one the limits picked.
  std::size_t odometry_arbitrated() const { return odometry_arbitrated_; }

 private:
  // The pose predicted from the odometry if its step is within the speed limits, else by
  // constant velocity; the other prediction as the alternative, where there is odometry.
  struct Predictions {
    PlanarPose primary;
    std::optional<PlanarPose> alternative;
    bool primary_is_odometry = false;
  };
  Predictions Predict(const TrackInput& input);
  // True unless the gyro turned the odometry since the anchor and the pose's heading, known to
  // sigma_rad, disagrees with it (max_gyro_chi2).
  bool GyroAgrees(const TrackInput& input, const PlanarPose& T_world_base, double sigma_rad) const;
  // True unless gyro-turned odometry has run since the anchor and the pose's position, known to
  // sigma_m, disagrees with it (max_odometry_chi2).
  bool OdometryAgrees(const TrackInput& input, const PlanarPose& T_world_base,
                      double sigma_m) const;

  TrackerOptions options_;
  KeyFrameMap* map_;
  RgbdFallback* rgbd_;
  KeyFrameBuffer buffer_;
  bool started_ = false;
  PlanarPose pose_;
  PlanarPose velocity_per_s_;  // body-frame motion per second, for the constant-velocity model
  TimestampNs last_stamp_ns_ = 0;
  std::optional<PlanarPose> last_odom_;
  // The pose and odometry at the last key frame (or since odometry last broke off): matches are
  // fused with the odometry from there.
  struct Anchor {
    PlanarPose T_world_base;
    PlanarPose T_odom_base;
    TimestampNs stamp_ns = 0;
    bool heading_from_gyro = false;  // and every odometry step since
  };
  std::optional<Anchor> anchor_;
  double path_length_m_ = 0;
  std::size_t odometry_rejected_ = 0;
  std::size_t odometry_arbitrated_ = 0;
};

}  // namespace littermap::reconstruct

#include "reconstruct/tracker.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "core/error.hpp"
#include "reconstruct/pose_graph.hpp"

namespace littermap::reconstruct {
namespace {

PlanarPose Scale(const PlanarPose& motion, double factor) {
  return {motion.x_m * factor, motion.y_m * factor, motion.theta_rad * factor};
}

// ratio: the match's inlier ratio, if the pose is a match's. A scan that overlays the map this
// well after a large turn found the heading: walls constrain a turn, so a wrong one shows.
bool Plausible(const TrackerOptions& options, const PlanarPose& from, const PlanarPose& predicted,
               const PlanarPose& matched, double ratio = 0) {
  const PlanarPose motion = Between(from, predicted);
  const PlanarPose correction = Between(predicted, matched);
  const double fraction = options.max_correction_fraction;
  const double max_turn_rad = ratio >= options.min_ratio_large_turn_correction
                                  ? options.max_large_turn_correction_rad
                                  : options.max_correction_rad;
  return std::hypot(correction.x_m, correction.y_m) <=
             options.max_correction_m + fraction * std::hypot(motion.x_m, motion.y_m) &&
         std::abs(correction.theta_rad) <= max_turn_rad + fraction * std::abs(motion.theta_rad);
}

// The match's information with a floor under its covariance: Gauss-Newton's information counts
// every echo as an independent measurement and sees neither correlated echoes nor the map's own
// error. Against wheels that hardly matters; against a gyro's heading, far more precise than any
// wheels', the bare information would still outweigh it, and a park's few trunks then turn the
// pose by degrees that the gyro never turned.
Eigen::Matrix3d FlooredInformation(const Eigen::Matrix3d& information, double floor_m,
                                   double floor_rad) {
  const Eigen::Matrix3d floor =
      Eigen::Vector3d(floor_m * floor_m, floor_m * floor_m, floor_rad * floor_rad).asDiagonal();
  // A tiny ridge keeps a match that leaves a direction open (information 0 there) invertible.
  const Eigen::Matrix3d covariance =
      (information + 1e-9 * Eigen::Matrix3d::Identity()).ldlt().solve(Eigen::Matrix3d::Identity());
  return (covariance + floor).ldlt().solve(Eigen::Matrix3d::Identity());
}

// The pose that best agrees with a match and the prediction, each weighted by its information
// (x, y, theta in the world frame, as the matcher's), and the information of that pose. With
// gyro_heading, the prediction's heading is a gyro's and the match's information is floored
// (FlooredInformation).
void FuseWithPrediction(const PlanarPose& predicted, const Eigen::Matrix3d& prediction_information,
                        bool gyro_heading, const TrackerOptions& options, TrackStep* step) {
  const Eigen::Vector3d matched_from_predicted(
      step->T_world_base.x_m - predicted.x_m, step->T_world_base.y_m - predicted.y_m,
      WrapAngle(step->T_world_base.theta_rad - predicted.theta_rad));
  const Eigen::Matrix3d match_information =
      gyro_heading ? FlooredInformation(step->information, options.match_sigma_floor_m,
                                        options.match_sigma_floor_rad)
                   : step->information;
  const Eigen::Matrix3d information = match_information + prediction_information;
  const Eigen::Vector3d fused =
      information.ldlt().solve(match_information * matched_from_predicted);
  step->T_world_base = {predicted.x_m + fused.x(), predicted.y_m + fused.y(),
                        WrapAngle(predicted.theta_rad + fused.z())};
  step->information = information;
}

bool Finite(const PlanarPose& p) {
  return std::isfinite(p.x_m) && std::isfinite(p.y_m) && std::isfinite(p.theta_rad);
}

}  // namespace

std::string_view RoutineName(Routine routine) {
  switch (routine) {
    case Routine::kGlobal:
      return "global";
    case Routine::kBuffer:
      return "buffer";
    case Routine::kRgbd:
      return "rgbd";
    case Routine::kOdometryOnly:
      return "odometry-only";
  }
  return "odometry-only";
}

void TrackerOptions::Validate() const {
  icp.Validate();
  key_frames.Validate();
  buffer.Validate();
  if (!(min_matching_ratio > 0 && min_matching_ratio <= 1) ||
      !(min_buffer_matching_ratio > 0 && min_buffer_matching_ratio <= 1) ||
      !(tilted_min_matching_ratio > 0 && tilted_min_matching_ratio <= 1) ||
      !(max_level_tilt_rad > 0) || !(rgbd_ratio_slack >= 0) || !(rgbd_sigma_m > 0) ||
      !(rgbd_sigma_rad > 0)) {
    throw UsageError(
        "tracker: matching ratios must be in (0, 1], max_level_tilt_rad > 0, rgbd_ratio_slack >= 0 "
        "and the RGB-D sigmas > 0");
  }
  if (!(min_ratio_large_turn_correction > 0 && min_ratio_large_turn_correction <= 1) ||
      !(max_large_turn_correction_rad >= max_correction_rad)) {
    throw UsageError(
        "tracker: min_ratio_large_turn_correction must be in (0, 1] and "
        "max_large_turn_correction_rad >= max_correction_rad");
  }
  if (!(max_gyro_chi2 > 0) || !(max_odometry_chi2 > 0) || !(match_sigma_floor_m > 0) ||
      !(match_sigma_floor_rad > 0)) {
    throw UsageError(
        "tracker: max_gyro_chi2, max_odometry_chi2 and the match sigma floors must be > 0");
  }
  if (!(max_arbitration_disagreement_m > 0) || !(max_arbitration_disagreement_rad > 0) ||
      !(min_arbitration_ratio_gain >= 0) || !(max_arbitration_gap_s >= 0)) {
    throw UsageError(
        "tracker: the arbitration disagreement limits must be > 0, its ratio gain and gap >= 0");
  }
  if (!(max_odometry_speed_m_s > 0) || !(max_odometry_turn_rate_rad_s > 0) ||
      !(max_scan_gap_s > 0)) {
    throw UsageError("tracker: odometry limits must be > 0");
  }
  if (!(odometry_sigma_m > 0) || !(odometry_sigma_rad > 0) || !(odometry_sigma_per_m >= 0) ||
      !(odometry_sigma_rad_per_m >= 0) || !(odometry_sigma_rad_per_rad >= 0) ||
      !(constant_velocity_sigma_factor >= 1) || !(gyro_sigma_rad > 0) ||
      !(gyro_sigma_rad_per_s >= 0) || !(gyro_sigma_rad_per_rad >= 0)) {
    throw UsageError(
        "tracker: odometry and gyro sigmas must be > 0 (their per-motion shares >= 0) and "
        "constant_velocity_sigma_factor >= 1");
  }
}

Tracker::Tracker(const TrackerOptions& options, KeyFrameMap* map, RgbdFallback* rgbd)
    : options_(options), map_(map), rgbd_(rgbd), buffer_(options.buffer) {
  options_.Validate();
}

Tracker::Predictions Tracker::Predict(const TrackInput& input) {
  const double dt = ToSeconds(input.stamp_ns - last_stamp_ns_);
  // Constant velocity (the motion of the last step continues), nothing after a long gap.
  const PlanarPose constant_velocity =
      Compose(pose_, dt <= options_.max_scan_gap_s ? Scale(velocity_per_s_, std::max(dt, 0.0))
                                                   : PlanarPose{});
  Predictions predictions{constant_velocity, std::nullopt, false};
  if (!input.T_odom_base || !last_odom_ || !Finite(*input.T_odom_base)) return predictions;
  const PlanarPose d = Between(*last_odom_, *input.T_odom_base);
  const PlanarPose odometry = Compose(pose_, d);
  const double span = std::max(dt, 0.0);
  if (std::hypot(d.x_m, d.y_m) <=
          std::max(options_.max_odometry_speed_m_s * span, options_.max_odometry_step_m) &&
      std::abs(d.theta_rad) <=
          std::max(options_.max_odometry_turn_rate_rad_s * span, options_.max_odometry_step_rad)) {
    return {odometry, constant_velocity, true};
  }
  return {constant_velocity, odometry, false};
}

Prediction PredictionOf(bool odometry_used, bool heading_from_gyro) {
  if (!odometry_used) return Prediction::kConstantVelocity;
  return heading_from_gyro ? Prediction::kGyroOdometry : Prediction::kOdometry;
}

Eigen::Matrix3d PredictionInformation(const TrackerOptions& options, const PlanarPose& motion,
                                      double elapsed_s, Prediction prediction) {
  const double distance_m = std::hypot(motion.x_m, motion.y_m);
  const double turn_rad = std::abs(motion.theta_rad);
  const double factor =
      prediction == Prediction::kConstantVelocity ? options.constant_velocity_sigma_factor : 1;
  const double sigma_m =
      factor * (options.odometry_sigma_m + options.odometry_sigma_per_m * distance_m);
  const double sigma_rad =
      prediction == Prediction::kGyroOdometry
          ? options.gyro_sigma_rad + options.gyro_sigma_rad_per_s * std::max(elapsed_s, 0.0) +
                options.gyro_sigma_rad_per_rad * turn_rad
          : factor * (options.odometry_sigma_rad + options.odometry_sigma_rad_per_m * distance_m +
                      options.odometry_sigma_rad_per_rad * turn_rad);
  return DiagonalInformation(sigma_m, sigma_rad);
}

TrackStep Tracker::Track(std::size_t scan_index, const TrackInput& input) {
  TrackStep step;
  step.scan_index = scan_index;
  if (!started_) {
    // The first scan defines the world frame.
    started_ = true;
    pose_ = {};
    step.routine = Routine::kGlobal;
    step.matching_ratio = 1;
  } else {
    const double dt = ToSeconds(input.stamp_ns - last_stamp_ns_);
    const Predictions predictions = Predict(input);
    PlanarPose predicted = predictions.primary;
    step.odometry_used = predictions.primary_is_odometry;
    // from_odometry: the match started from the odometry's prediction, which it must then agree
    // with (OdometryAgrees); the laser's arbitration against broken odometry starts elsewhere.
    // Tilted beyond level, the scan plane sweeps other heights of the scene than the map's: only
    // a match that overlays most of the scan is the laser's.
    const bool steep = input.tilt && TiltAngle(*input.tilt) > options_.max_level_tilt_rad;
    const double min_ratio =
        steep ? std::max(options_.tilted_min_matching_ratio, options_.min_matching_ratio)
              : options_.min_matching_ratio;
    const double min_buffer_ratio =
        steep ? std::max(options_.tilted_min_matching_ratio, options_.min_buffer_matching_ratio)
              : options_.min_buffer_matching_ratio;
    const auto accepted = [&](const IcpResult& match, const PlanarPose& from, bool from_odometry) {
      return match.converged && match.inlier_ratio >= min_ratio &&
             Plausible(options_, pose_, from, match.T_target_source, match.inlier_ratio) &&
             GyroAgrees(input, match.T_target_source, options_.match_sigma_floor_rad) &&
             (!from_odometry ||
              OdometryAgrees(input, match.T_target_source, options_.match_sigma_floor_m));
    };
    IcpResult global = MatchIcp(input.points_base, map_->LocalTarget(), predicted, options_.icp);
    step.matching_ratio = global.inlier_ratio;
    if (!accepted(global, predicted, step.odometry_used) && predictions.alternative &&
        dt <= options_.max_arbitration_gap_s &&
        !Plausible(options_, pose_, predicted, *predictions.alternative)) {
      // The odometry and the constant-velocity model disagree by more than a match may correct,
      // and the laser did not confirm the one believed: a wheel that slipped, odometry that
      // stalled and then caught up, or odometry that really moved that fast. The prediction the
      // laser confirms wins.
      IcpResult other =
          MatchIcp(input.points_base, map_->LocalTarget(), *predictions.alternative, options_.icp);
      // The other start must overlay clearly more of the scan, or lead the matcher to the same
      // pose: a scan that pins the pose down has one basin, whereas along a corridor each start
      // slides to a place of its own, overlaying about as much.
      const PlanarPose apart = Between(global.T_target_source, other.T_target_source);
      const bool same_pose =
          global.converged &&
          std::hypot(apart.x_m, apart.y_m) <= options_.max_arbitration_disagreement_m &&
          std::abs(apart.theta_rad) <= options_.max_arbitration_disagreement_rad;
      if (accepted(other, *predictions.alternative, !predictions.primary_is_odometry) &&
          (same_pose ||
           other.inlier_ratio >= global.inlier_ratio + options_.min_arbitration_ratio_gain)) {
        predicted = *predictions.alternative;
        step.odometry_used = !predictions.primary_is_odometry;
        global = std::move(other);
        step.matching_ratio = global.inlier_ratio;
        ++odometry_arbitrated_;
      }
    }
    step.T_world_base = predicted;
    if (accepted(global, predicted, step.odometry_used)) {
      step.routine = Routine::kGlobal;
      step.T_world_base = global.T_target_source;
      step.information = global.information;
    } else if (const BufferedFrame* near = buffer_.Nearest(predicted)) {
      const IcpTarget target(TransformPoints(near->T_world_base, near->points_base), options_.icp);
      const IcpResult local = MatchIcp(input.points_base, target, predicted, options_.icp);
      if (local.converged && local.inlier_ratio >= min_buffer_ratio &&
          Plausible(options_, pose_, predicted, local.T_target_source) &&
          GyroAgrees(input, local.T_target_source, options_.match_sigma_floor_rad) &&
          (!step.odometry_used ||
           OdometryAgrees(input, local.T_target_source, options_.match_sigma_floor_m))) {
        step.routine = Routine::kBuffer;
        step.T_world_base = local.T_target_source;
        step.matching_ratio = local.inlier_ratio;
        step.information = local.information;
      }
    }
    if (step.information.isZero() && rgbd_ != nullptr) {
      if (const auto rgbd_pose = rgbd_->AlignAt(input, predicted, *map_)) {
        // Verified by the laser where it still sees the map from the RGB-D pose, or by
        // agreeing with the prediction where it does not (the scan pattern changed).
        const double ratio =
            MatchIcp(input.points_base, map_->LocalTarget(), *rgbd_pose, options_.icp).inlier_ratio;
        if ((ratio >= options_.min_matching_ratio - options_.rgbd_ratio_slack ||
             Plausible(options_, pose_, predicted, *rgbd_pose)) &&
            GyroAgrees(input, *rgbd_pose, options_.rgbd_sigma_rad)) {
          step.routine = Routine::kRgbd;
          step.T_world_base = *rgbd_pose;
          step.matching_ratio = ratio;
          step.information = DiagonalInformation(options_.rgbd_sigma_m, options_.rgbd_sigma_rad);
        }
      }
    }
    // A gyro anchor's odometry must be turned by the gyro all along; once the gyro turns it
    // (its first readings), the anchor is taken again, so the gyro's checks hold from there.
    if (anchor_ && anchor_->heading_from_gyro != input.heading_from_gyro) anchor_.reset();
    if (step.information.isZero()) {
      step.routine = Routine::kOdometryOnly;
    } else if (step.routine == Routine::kRgbd) {
      // Routine 3 runs because the prediction failed to match: it is not fused with its
      // position. A gyro's heading is still better than the camera's.
      if (step.odometry_used && input.heading_from_gyro) {
        Eigen::Matrix3d heading = Eigen::Matrix3d::Zero();
        heading(2, 2) = PredictionInformation(options_, Between(pose_, predicted), dt,
                                              Prediction::kGyroOdometry)(2, 2);
        FuseWithPrediction(predicted, heading, true, options_, &step);
      }
    } else if (step.odometry_used && anchor_) {
      // The odometry since the anchor, not since the last scan: a match that slides a little
      // every scan cannot add the slides up between two key frames.
      const PlanarPose from_anchor =
          Compose(anchor_->T_world_base, Between(anchor_->T_odom_base, *input.T_odom_base));
      FuseWithPrediction(
          from_anchor,
          PredictionInformation(options_, Between(anchor_->T_world_base, from_anchor),
                                ToSeconds(input.stamp_ns - anchor_->stamp_ns),
                                PredictionOf(true, anchor_->heading_from_gyro)),
          anchor_->heading_from_gyro, options_, &step);
    } else {
      const Prediction prediction = PredictionOf(step.odometry_used, input.heading_from_gyro);
      FuseWithPrediction(predicted,
                         PredictionInformation(options_, Between(pose_, predicted), dt, prediction),
                         prediction == Prediction::kGyroOdometry, options_, &step);
    }
    if (!step.odometry_used) {
      anchor_.reset();
      if (predictions.alternative) ++odometry_rejected_;  // there was odometry to use
    }
    const PlanarPose moved = Between(pose_, step.T_world_base);
    velocity_per_s_ = dt > 1e-6 ? Scale(moved, 1.0 / dt) : PlanarPose{};
    path_length_m_ += std::hypot(moved.x_m, moved.y_m);
    pose_ = step.T_world_base;
  }
  step.T_world_base = pose_;
  last_stamp_ns_ = input.stamp_ns;
  // Without odometry at this scan the next increment would span the gap on top of the motion
  // already predicted for it: start over from the next odometry.
  last_odom_.reset();
  if (input.T_odom_base && Finite(*input.T_odom_base)) last_odom_ = input.T_odom_base;

  // Routine 2 success forces a key frame: "fuse the scan so the global map learns".
  const bool force = step.routine == Routine::kBuffer;
  // Scans the laser did not place still make key frames: otherwise a long failure would leave the
  // top map behind the robot and matching could never recover.
  if (force || map_->NeedsKeyFrame(pose_)) {
    KeyFrame key_frame{scan_index, input.stamp_ns, pose_, input.points_base, path_length_m_, {}};
    step.key_frame = map_->Add(std::move(key_frame));
    step.new_key_frame = true;
    anchor_.reset();
  } else {
    step.key_frame = map_->key_frames().size() - 1;
  }
  if (!anchor_ && input.T_odom_base && Finite(*input.T_odom_base)) {
    anchor_ = Anchor{pose_, *input.T_odom_base, input.stamp_ns, input.heading_from_gyro};
  }
  if (buffer_.NeedsFrame(pose_) && step.routine != Routine::kOdometryOnly &&
      step.routine != Routine::kRgbd) {
    buffer_.Add({pose_, input.points_base});
  }
  if (rgbd_ != nullptr) rgbd_->OnTracked(input, step, *map_);
  return step;
}

bool Tracker::GyroAgrees(const TrackInput& input, const PlanarPose& T_world_base,
                         double sigma_rad) const {
  if (!input.heading_from_gyro || !anchor_ || !anchor_->heading_from_gyro || !input.T_odom_base ||
      !Finite(*input.T_odom_base)) {
    return true;  // no gyro heading since the anchor to check against
  }
  const PlanarPose turned = Between(anchor_->T_odom_base, *input.T_odom_base);
  const double predicted_rad = anchor_->T_world_base.theta_rad + turned.theta_rad;
  const double gyro_sigma_rad =
      options_.gyro_sigma_rad +
      options_.gyro_sigma_rad_per_s * std::max(ToSeconds(input.stamp_ns - anchor_->stamp_ns), 0.0) +
      options_.gyro_sigma_rad_per_rad * std::abs(turned.theta_rad);
  const double variance = gyro_sigma_rad * gyro_sigma_rad + sigma_rad * sigma_rad;
  const double difference = WrapAngle(T_world_base.theta_rad - predicted_rad);
  return difference * difference <= options_.max_gyro_chi2 * variance;
}

bool Tracker::OdometryAgrees(const TrackInput& input, const PlanarPose& T_world_base,
                             double sigma_m) const {
  // Only odometry turned by a gyro: the model's covariance grows with the distance driven, and
  // a wheel heading's error shifts the position sideways beyond it.
  if (!anchor_ || !anchor_->heading_from_gyro || !input.heading_from_gyro || !input.T_odom_base ||
      !Finite(*input.T_odom_base)) {
    return true;
  }
  const PlanarPose moved = Between(anchor_->T_odom_base, *input.T_odom_base);
  const PlanarPose predicted = Compose(anchor_->T_world_base, moved);
  const Eigen::Matrix3d information =
      PredictionInformation(options_, moved, ToSeconds(input.stamp_ns - anchor_->stamp_ns),
                            PredictionOf(true, anchor_->heading_from_gyro));
  // PredictionInformation is diagonal and the same in x and y.
  const double variance = 1 / information(0, 0) + sigma_m * sigma_m;
  const double dx = T_world_base.x_m - predicted.x_m, dy = T_world_base.y_m - predicted.y_m;
  return (dx * dx + dy * dy) / variance <= options_.max_odometry_chi2;
}

void Tracker::OnKeyFramesMoved(const PlanarPose& T_new_old) {
  pose_ = Compose(T_new_old, pose_);
  if (anchor_) anchor_->T_world_base = Compose(T_new_old, anchor_->T_world_base);
  buffer_.Correct(T_new_old);
}

}  // namespace littermap::reconstruct

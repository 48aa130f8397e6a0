#include "reconstruct/slam_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

bool LoopFits(const PoseGraphEdge& edge, const std::vector<PlanarPose>& poses,
              const SlamOptions& options) {
  const PlanarPose residual = Between(edge.T_from_to, Between(poses[edge.from], poses[edge.to]));
  return std::hypot(residual.x_m, residual.y_m) <= options.max_loop_residual_m &&
         std::abs(residual.theta_rad) <= options.max_loop_residual_rad;
}

}  // namespace

void SlamOptions::Validate() const {
  points.Validate();
  moving_echoes.Validate();
  tracker.Validate();
  loops.Validate();
  graph.Validate();
  grid.Validate();
  alignment.Validate();
  // Map points are kept in centimetres in 16 bits (SlamPipeline::MapPoint).
  if (!(map_max_range_m > 0) || map_max_range_m > 300) {
    throw UsageError("slam: map_max_range_m must be in (0, 300]");
  }
  if (!(edge_sigma_floor_m > 0) || !(edge_sigma_floor_rad > 0) || !(odometry_sigma_m > 0) ||
      !(odometry_sigma_rad > 0)) {
    throw UsageError("slam: edge sigma floors and odometry sigmas must be > 0");
  }
  if (!(max_loop_residual_m > 0) || !(max_loop_residual_rad > 0)) {
    throw UsageError("slam: loop residual limits must be > 0");
  }
  if (!(max_final_loop_chi2 > 0)) throw UsageError("slam: max_final_loop_chi2 must be > 0");
  if (!(wide_loop_search_every_m > 0)) {
    throw UsageError("slam: wide_loop_search_every_m must be > 0");
  }
}

SlamPipeline::SlamPipeline(const SlamOptions& options, const PlanarPose& T_base_laser,
                           RgbdFallback* rgbd)
    : options_((options.Validate(), options)),
      T_base_laser_(T_base_laser),
      map_(options.tracker.key_frames, options.tracker.icp),
      tracker_(options.tracker, &map_, rgbd),
      loop_closer_(options.loops),
      moving_echoes_(options.moving_echoes),
      terrain_relief_(options.moving_echoes.relief_window_m),
      grid_(options.grid) {}

void SlamPipeline::AddScan(const LaserScan& scan, const std::optional<GyroOdometryPose>& odometry,
                           const std::optional<Tilt>& tilt) {
  const std::optional<PlanarPose> T_odom_base =
      odometry ? std::optional(odometry->T_odom_base) : std::nullopt;
  ++quality_.scans_in;
  if (last_stamp_ns_ && scan.stamp_ns < *last_stamp_ns_) {
    ++quality_.stamps_backwards;  // a TUM trajectory cannot go back in time: drop the scan
    return;
  }
  if (last_stamp_ns_ && scan.stamp_ns == *last_stamp_ns_) {
    ++quality_.stamps_duplicate;
    return;
  }
  last_stamp_ns_ = scan.stamp_ns;
  tilted_ = tilted_ || tilt.has_value();
  ScanPoints points = ScanToPoints(scan, T_base_laser_, options_.points, tilt);
  quality_.ground_echoes += points.ground_beams;
  TrackInput input;
  input.stamp_ns = scan.stamp_ns;
  input.T_odom_base = T_odom_base;
  input.heading_from_gyro = odometry && odometry->heading_from_gyro;
  input.tilt = tilt;
  Points2 map_points_base = std::move(points.points_base);
  if (points.valid_beams >= options_.min_scan_points) {
    input.points_base = VoxelDownsample(map_points_base, options_.scan_voxel_size_m);
    // Wheels alone can slip by degrees in a quarter of a second: only a gyro's heading will do.
    const MovingEchoMode mode = options_.moving_echoes.mode;
    if (mode != MovingEchoMode::kOff && tilt && odometry && odometry->heading_from_gyro) {
      // Every scan is kept for comparison; its echoes are filtered where the terrain calls for it.
      const double relief_m = terrain_relief_.Add(odometry->T_odom_base, odometry->z_m);
      if (mode != MovingEchoMode::kOn && relief_m <= options_.moving_echoes.min_relief_m) {
        moving_echoes_.Remember(scan.stamp_ns, odometry->T_odom_base, input.points_base);
      } else {
        MovingEchoResult still =
            moving_echoes_.Filter(scan.stamp_ns, odometry->T_odom_base, input.points_base);
        ++quality_.scans_moving_echo_filtered;
        quality_.moving_echoes += still.moving;
        if (still.given_up) ++quality_.scans_moving_echoes;  // tracked like a scan without echoes
        input.points_base = still.given_up ? Points2{} : still.points_base;
        map_points_base = std::move(still.points_base);  // the map does not draw the arcs either
      }
    }
  } else {
    ++quality_.scans_without_echoes;  // tracked on the prediction alone
  }
  if (!T_odom_base) ++quality_.odometry_missing;
  const TrackStep step = tracker_.Track(scans_.size(), input);
  ++quality_.routine_counts[static_cast<std::size_t>(step.routine)];
  ++quality_.scans_tracked;
  ScanRecord record;
  record.scan_index = scans_.size();
  record.stamp_ns = scan.stamp_ns;
  record.routine = step.routine;
  record.matching_ratio = step.matching_ratio;
  record.key_frame = step.key_frame;
  record.T_keyframe_base =
      Between(map_.key_frames()[step.key_frame].T_world_base, step.T_world_base);
  record.T_world_base = step.T_world_base;
  record.T_odom_base = T_odom_base;
  record.odometry_used = step.odometry_used;
  record.heading_from_gyro = input.heading_from_gyro;
  if (odometry) {
    if (!first_odometry_z_m_) first_odometry_z_m_ = odometry->z_m;
    record.z_m = odometry->z_m - *first_odometry_z_m_;
  } else if (!scans_.empty()) {
    record.z_m = scans_.back().z_m;
  }
  scans_.push_back(record);
  StoreMapPoints(map_points_base);
  if (step.new_key_frame && step.key_frame > 0) {
    AddGraphEdge(step);
    if (options_.loop_closure) CloseLoops(step.key_frame);
  }
}

void SlamPipeline::StoreMapPoints(const Points2& points_base) {
  const Points2 cells = VoxelDownsample(points_base, options_.grid.cell_size_m);
  const Eigen::Vector2d laser_base(T_base_laser_.x_m, T_base_laser_.y_m);
  const double max_range_sq = options_.map_max_range_m * options_.map_max_range_m;
  const auto in_range = [&](const Eigen::Vector2d& p) {
    return (p - laser_base).squaredNorm() <= max_range_sq;
  };
  std::vector<MapPoint>& stored = map_points_base_.emplace_back();
  stored.reserve(static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), in_range)));
  for (const Eigen::Vector2d& p : cells) {
    if (!in_range(p)) continue;
    stored.push_back({static_cast<std::int16_t>(std::lround(p.x() * 100)),
                      static_cast<std::int16_t>(std::lround(p.y() * 100))});
  }
}

void SlamPipeline::AddGraphEdge(const TrackStep& step) {
  const auto& frames = map_.key_frames();
  PoseGraphEdge edge;
  edge.from = step.key_frame - 1;
  edge.to = step.key_frame;
  edge.T_from_to = Between(frames[edge.from].T_world_base, frames[edge.to].T_world_base);
  edge.information =
      step.routine == Routine::kOdometryOnly
          ? DiagonalInformation(options_.odometry_sigma_m, options_.odometry_sigma_rad)
          : EdgeInformation(step.information, frames[edge.from].T_world_base.theta_rad,
                            options_.edge_sigma_floor_m, options_.edge_sigma_floor_rad);
  edges_.push_back(edge);
}

void SlamPipeline::CloseLoops(std::size_t key_frame) {
  if (any_loop_ && key_frame < last_loop_key_frame_ + options_.loop_cooldown_key_frames) return;
  const double path_m = map_.key_frames()[key_frame].path_length_m;
  const bool wide = path_m - last_wide_search_path_m_ >= options_.wide_loop_search_every_m;
  if (wide) last_wide_search_path_m_ = path_m;
  const LoopAttempt attempt = loop_closer_.TryClose(
      map_, key_frame, GraphDistances(map_.key_frames().size(), edges_, key_frame), wide);
  switch (attempt.verdict) {
    case LoopVerdict::kNoCandidate:
      return;
    case LoopVerdict::kRejectedMatch:
      ++quality_.loop_candidates;
      ++quality_.loops_rejected_match;
      return;
    case LoopVerdict::kRejectedDisagreement:
      ++quality_.loop_candidates;
      ++quality_.loops_rejected_disagreement;
      return;
    case LoopVerdict::kAccepted:
      ++quality_.loop_candidates;
      break;
  }
  PoseGraphEdge edge = *attempt.edge;
  edge.information = EdgeInformation(attempt.match.information,
                                     map_.key_frames()[edge.from].T_world_base.theta_rad,
                                     options_.edge_sigma_floor_m, options_.edge_sigma_floor_rad);
  edges_.push_back(edge);
  unchecked_loops_.push_back(edges_.size() - 1);
  last_loop_key_frame_ = key_frame;
  any_loop_ = true;
  Optimise();
}

void SlamPipeline::Optimise() {
  const std::vector<PlanarPose> before = map_.Poses();
  std::vector<PlanarPose> poses = before;
  PoseGraphResult result = OptimizePoseGraph(&poses, edges_, options_.graph);
  ++quality_.optimisations;
  // Consistency after optimisation: a loop the graph cannot satisfy is taken out again, and the
  // graph optimised without it (false loops must not stay in).
  bool removed = false;
  for (std::size_t index : unchecked_loops_) {
    PoseGraphEdge& edge = edges_[index];
    if (!result.usable || !LoopFits(edge, poses, options_)) {
      edge.information.setZero();  // marked for removal
      removed = true;
      ++quality_.loops_rejected_after_optimisation;
    } else {
      ++quality_.loops_accepted;
    }
  }
  unchecked_loops_.clear();
  if (removed) {
    std::erase_if(edges_, [](const PoseGraphEdge& e) { return e.information.isZero(); });
    poses = before;
    result = OptimizePoseGraph(&poses, edges_, options_.graph);
    ++quality_.optimisations;
  }
  if (!result.usable) return;
  quality_.final_cost = result.final_cost;
  const PlanarPose T_new_old = Compose(poses.back(), Inverse(before.back()));
  map_.SetPoses(poses);
  tracker_.OnKeyFramesMoved(T_new_old);
}

void SlamPipeline::Finish() {
  if (!unchecked_loops_.empty()) Optimise();
  PruneFinalLoops();
  if (options_.alignment_mode == AlignmentMode::kOn ||
      (options_.alignment_mode == AlignmentMode::kAuto && !tilted_)) {
    AlignKeyFrames();
  }
  quality_.key_frames = map_.key_frames().size();
  quality_.odometry_rejected = tracker_.odometry_rejected();
  quality_.odometry_arbitrated = tracker_.odometry_arbitrated();
  const auto& frames = map_.key_frames();
  const auto hits_of = [&](std::size_t i) {
    Points2 hits;
    hits.reserve(map_points_base_[i].size());
    for (const MapPoint& point : map_points_base_[i]) {
      hits.push_back(
          Transform(scans_[i].T_world_base, Eigen::Vector2d(point.x_cm, point.y_cm) / 100));
    }
    return hits;
  };
  // Final poses and the extent of the map first, so the grid is allocated once.
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    ScanRecord& record = scans_[i];
    record.T_world_base = Compose(frames[record.key_frame].T_world_base, record.T_keyframe_base);
    const PlanarPose T_world_laser = Compose(record.T_world_base, T_base_laser_);
    for (const Eigen::Vector2d& p : hits_of(i)) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    low = low.cwiseMin(Eigen::Vector2d(T_world_laser.x_m, T_world_laser.y_m));
    high = high.cwiseMax(Eigen::Vector2d(T_world_laser.x_m, T_world_laser.y_m));
  }
  grid_.Cover(low, high);
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    const PlanarPose T_world_laser = Compose(scans_[i].T_world_base, T_base_laser_);
    grid_.InsertScan({T_world_laser.x_m, T_world_laser.y_m}, hits_of(i));
  }
}

void SlamPipeline::PruneFinalLoops() {
  std::vector<PlanarPose> poses = map_.Poses();
  const LoopPruning pruning =
      PruneLoops(&poses, &edges_, options_.max_final_loop_chi2, options_.graph);
  if (pruning.removed == 0) return;
  // Edges removed before an unusable solution stay removed; the poses are the last usable ones.
  quality_.loops_accepted -= pruning.removed;
  quality_.loops_rejected_after_optimisation += pruning.removed;
  quality_.optimisations += pruning.removed;
  if (pruning.usable) quality_.final_cost = pruning.final_cost;
  map_.SetPoses(poses);
}

std::vector<PoseGraphEdge> SlamPipeline::KeyFrameOdometry() const {
  const auto& frames = map_.key_frames();
  std::vector<PoseGraphEdge> odometry(frames.size() > 0 ? frames.size() - 1 : 0);
  std::vector<bool> found(odometry.size(), false);
  for (const PoseGraphEdge& edge : edges_) {
    if (edge.loop || edge.to != edge.from + 1 || edge.to >= frames.size()) continue;
    odometry[edge.from] = edge;
    found[edge.from] = true;
  }
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const ScanRecord& a = scans_[frames[k - 1].scan_index];
    const ScanRecord& b = scans_[frames[k].scan_index];
    if (b.scan_index != a.scan_index + 1 || !a.T_odom_base || !b.odometry_used) continue;
    PoseGraphEdge& edge = odometry[k - 1];
    edge.from = k - 1;
    edge.to = k;
    edge.T_from_to = Between(*a.T_odom_base, *b.T_odom_base);
    edge.information = PredictionInformation(
        options_.tracker, edge.T_from_to, ToSeconds(b.stamp_ns - a.stamp_ns),
        b.heading_from_gyro ? Prediction::kGyroOdometry : Prediction::kOdometry);
    found[k - 1] = true;
  }
  std::vector<PoseGraphEdge> kept;
  for (std::size_t k = 0; k < odometry.size(); ++k) {
    if (found[k]) kept.push_back(odometry[k]);
  }
  return kept;
}

void SlamPipeline::AlignKeyFrames() {
  std::vector<PlanarPose> poses = map_.Poses();
  quality_.alignment =
      AlignScans(map_.key_frames(), KeyFrameOdometry(), &poses, options_.alignment);
  if (quality_.alignment.rounds > 0) map_.SetPoses(poses);
}

std::vector<std::pair<TimestampNs, PlanarPose>> SlamPipeline::KeyFramePoses() const {
  std::vector<std::pair<TimestampNs, PlanarPose>> poses;
  for (const KeyFrame& k : map_.key_frames()) poses.emplace_back(k.stamp_ns, k.T_world_base);
  return poses;
}

}  // namespace littermap::reconstruct

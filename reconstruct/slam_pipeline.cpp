#include "reconstruct/slam_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

// `over` applied to the pose graph's edges joined by the landmark links (which count for distances
// over the graph only), without a copy when there are none.
template <typename Over>
auto OverEdgesAndLinks(const std::vector<PoseGraphEdge>& edges,
                       const std::vector<PoseGraphEdge>& links, const Over& over) {
  if (links.empty()) return over(edges);
  std::vector<PoseGraphEdge> all = edges;
  all.insert(all.end(), links.begin(), links.end());
  return over(all);
}

bool LoopFits(const PoseGraphEdge& edge, const std::vector<PlanarPose>& poses,
              const SlamOptions& options) {
  const PlanarPose residual = Between(edge.T_from_to, Between(poses[edge.from], poses[edge.to]));
  return std::hypot(residual.x_m, residual.y_m) <= options.max_loop_residual_m &&
         std::abs(residual.theta_rad) <= options.max_loop_residual_rad;
}

// Whether a loop edge of the graph is the one a record (a scan's or a camera's loop) added.
bool IsEdgeOf(const PoseGraphEdge& edge, const LoopRecord& record) {
  return edge.loop && record.kind != LoopKind::kLandmark &&
         edge.camera == (record.kind == LoopKind::kCamera) && edge.from == record.from_key_frame &&
         edge.to == record.to_key_frame;
}

}  // namespace

void SlamOptions::Validate() const {
  points.Validate();
  moving_echoes.Validate();
  tracker.Validate();
  loops.Validate();
  loop_consistency.Validate();
  graph.Validate();
  grid.Validate();
  alignment.Validate();
  landmark_extraction.Validate();
  landmark_map.Validate();
  if (!(landmark_loop_search_every_m > 0) || !(max_landmark_loop_chi2 > 0) ||
      landmark_optimise_every_key_frames < 1 || !(landmark_max_rocking_rad >= 0) ||
      !(landmark_rocking_window_s > 0)) {
    throw UsageError(
        "slam: landmark_loop_search_every_m and max_landmark_loop_chi2 must be > 0, "
        "landmark_optimise_every_key_frames >= 1, landmark_max_rocking_rad >= 0, "
        "landmark_rocking_window_s > 0");
  }
  // Map points are kept in centimetres in 16 bits (SlamPipeline::MapPoint).
  if (!(map_max_range_m > 0) || map_max_range_m > 300) {
    throw UsageError("slam: map_max_range_m must be in (0, 300]");
  }
  if (!(edge_sigma_floor_m > 0) || !(edge_sigma_floor_rad > 0) ||
      !(gyro_edge_sigma_floor_rad > 0) || !(soft_edge_sigma_floor_rad > 0) ||
      !(odometry_sigma_m > 0) || !(odometry_sigma_rad > 0) || !(refine_hold_sigma_m > 0) ||
      !(refine_hold_sigma_rad > 0)) {
    throw UsageError("slam: edge sigma floors, odometry and refinement hold sigmas must be > 0");
  }
  if (!(max_loop_residual_m > 0) || !(max_loop_residual_rad > 0)) {
    throw UsageError("slam: loop residual limits must be > 0");
  }
  if (!(gyro_turn_sigma_rad_per_sqrt_s >= 0)) {
    throw UsageError("slam: gyro_turn_sigma_rad_per_sqrt_s must be >= 0");
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
      rgbd_(rgbd),
      map_(options.tracker.key_frames, options.tracker.icp),
      tracker_(options.tracker, &map_, rgbd),
      loop_closer_(options.loops),
      landmark_map_(options.landmark_map),
      moving_echoes_(options.moving_echoes),
      terrain_relief_(options.moving_echoes.relief_window_m),
      tilt_rocking_(options.landmark_rocking_window_s),
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
  gyro_heading_ = gyro_heading_ || (odometry && odometry->heading_from_gyro);
  if (tilt) tilt_rocking_.Add(scan.stamp_ns, *tilt);
  ScanPoints points = ScanToPoints(scan, T_base_laser_, options_.points, tilt);
  quality_.ground_echoes += points.ground_beams;
  TrackInput input;
  input.stamp_ns = scan.stamp_ns;
  input.T_odom_base = T_odom_base;
  input.heading_from_gyro = odometry && odometry->heading_from_gyro;
  input.tilt = tilt;
  // Every echo in beam order: drawn into the map, and searched for landmarks at a key frame.
  const Points2 echoes_base = std::move(points.points_base);
  std::optional<Points2> still_base;  // the echoes the moving-echo filter kept, where it ran
  if (points.valid_beams >= options_.min_scan_points) {
    input.points_base = VoxelDownsample(echoes_base, options_.scan_voxel_size_m);
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
        still_base = std::move(still.points_base);  // the map does not draw the arcs either
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
  scans_without_gyro_.push_back((scans_without_gyro_.empty() ? 0 : scans_without_gyro_.back()) +
                                (T_odom_base && input.heading_from_gyro ? 0 : 1));
  scans_by_camera_.push_back((scans_by_camera_.empty() ? 0 : scans_by_camera_.back()) +
                             (step.routine == Routine::kRgbd ? 1 : 0));
  StoreMapPoints(still_base ? *still_base : echoes_base);
  if (step.new_key_frame) {
    if (step.key_frame > 0) AddGraphEdge(input, step, still_base.has_value());
    // A scan taken while a root or a kerb rocks the base cuts trunks off their usual circle.
    if (options_.landmarks &&
        !(tilt && tilt_rocking_.LatestRockingRad() > options_.landmark_max_rocking_rad)) {
      const KeyFrame& frame = map_.key_frames()[step.key_frame];
      const std::vector<LandmarkObservation> circles =
          ExtractLandmarks(echoes_base, {T_base_laser_.x_m, T_base_laser_.y_m},
                           scan.angle_increment_rad, options_.landmark_extraction);
      quality_.landmark_sightings += circles.size();
      quality_.landmark_associations += landmark_map_.AddKeyFrame(
          step.key_frame, frame.T_world_base, frame.path_length_m, circles);
    }
    if (options_.loop_closure && step.key_frame > 0) {
      CloseLoops(step.key_frame);
      if (options_.landmarks) CloseLandmarkLoops(step.key_frame);
      if (rgbd_ != nullptr) CloseCameraLoop(input, step);
    }
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

void SlamPipeline::AddGraphEdge(const TrackInput& input, const TrackStep& step,
                                bool echoes_filtered) {
  const auto& frames = map_.key_frames();
  PoseGraphEdge edge;
  edge.from = step.key_frame - 1;
  edge.to = step.key_frame;
  const bool through_camera = scans_by_camera_[frames[edge.to].scan_index] !=
                              scans_by_camera_[frames[edge.from].scan_index];
  edge.T_from_to = Between(frames[edge.from].T_world_base, frames[edge.to].T_world_base);
  if (step.routine == Routine::kOdometryOnly) {
    edge.information = DiagonalInformation(options_.odometry_sigma_m, options_.odometry_sigma_rad);
    // How far the heading can have turned wrong over the edge, by the tracker's motion model.
    const Eigen::Matrix3d model =
        PredictionInformation(options_.tracker, edge.T_from_to,
                              ToSeconds(frames[edge.to].stamp_ns - frames[edge.from].stamp_ns),
                              PredictionOf(step.odometry_used, input.heading_from_gyro));
    edge.odometry_sigma_rad = 1 / std::sqrt(model(2, 2));
  } else {
    const double floor_rad = through_camera ? options_.soft_edge_sigma_floor_rad
                             : GyroTurnedBetween(edge.from, edge.to)
                                 ? options_.gyro_edge_sigma_floor_rad
                                 : options_.edge_sigma_floor_rad;
    edge.information = EdgeInformation(step.information, frames[edge.from].T_world_base.theta_rad,
                                       options_.edge_sigma_floor_m, floor_rad);
  }
  edges_.push_back(edge);
  const std::optional<double> gyro_rad =
      options_.gyro_turn_sigma_rad_per_sqrt_s > 0 && (echoes_filtered || through_camera)
          ? GyroTurnRad(edge.from, edge.to)
          : std::nullopt;
  if (gyro_rad) {
    PoseGraphEdge gyro;
    gyro.from = edge.from;
    gyro.to = edge.to;
    gyro.heading_only = true;
    gyro.T_from_to.theta_rad = WrapAngle(*gyro_rad);
    const double sigma_rad =
        options_.gyro_turn_sigma_rad_per_sqrt_s *
        std::sqrt(std::max(ToSeconds(frames[edge.to].stamp_ns - frames[edge.from].stamp_ns), 1e-3));
    gyro.information = Eigen::Vector3d(0, 0, 1 / (sigma_rad * sigma_rad)).asDiagonal();
    edges_.push_back(gyro);
  }
}

void SlamPipeline::CloseLoops(std::size_t key_frame, bool end_of_run) {
  if (ConfirmTentativeLoop(key_frame)) return;
  if (!end_of_run && any_loop_ &&
      key_frame < last_loop_key_frame_ + options_.loop_cooldown_key_frames) {
    return;
  }
  const double path_m = map_.key_frames()[key_frame].path_length_m;
  const bool wide =
      end_of_run || path_m - last_wide_search_path_m_ >= options_.wide_loop_search_every_m;
  if (wide) last_wide_search_path_m_ = path_m;
  LoopAttempt attempt = loop_closer_.TryClose(map_, key_frame, ReachFrom(key_frame), wide);
  HoldToGyro(&attempt);
  switch (attempt.verdict) {
    case LoopVerdict::kNoCandidate:
      return;
    case LoopVerdict::kRejectedMatch:
      RecordScanLoop(attempt, key_frame, LoopOutcome::kRejectedMatch);
      return;
    case LoopVerdict::kRejectedDisagreement:
      RecordScanLoop(attempt, key_frame, LoopOutcome::kRejectedDisagreement);
      return;
    case LoopVerdict::kRejectedDegenerate:
      RecordScanLoop(attempt, key_frame, LoopOutcome::kRejectedDegenerate);
      return;
    case LoopVerdict::kTentative:
      if (tentative_loop_) DropTentativeLoop();  // the older one was not confirmed
      tentative_loop_ = TentativeLoop{attempt, attempt.match.T_target_source};
      tentative_record_ = RecordScanLoop(attempt, key_frame, LoopOutcome::kTentative);
      return;
    case LoopVerdict::kAccepted:
      break;
  }
  RecordScanLoop(attempt, key_frame, LoopOutcome::kAccepted);
  AddLoopEdge(attempt);
  Optimise();
}

std::size_t SlamPipeline::RecordScanLoop(const LoopAttempt& attempt, std::size_t key_frame,
                                         LoopOutcome outcome) {
  const bool matched = attempt.match.converged;
  const PlanarPose correction =
      matched ? Between(map_.key_frames()[key_frame].T_world_base, attempt.match.T_target_source)
              : PlanarPose{};
  const std::size_t index =
      RecordLoop(LoopKind::kScan, attempt.candidate, key_frame, correction, outcome);
  if (matched) loops_[index].matching_ratio = attempt.match.inlier_ratio;
  loops_[index].weakest_sigma_m = attempt.weakest_sigma_m;
  return index;
}

std::size_t SlamPipeline::RecordLoop(LoopKind kind, std::size_t from, std::size_t to,
                                     const PlanarPose& correction, LoopOutcome outcome) {
  const auto& frames = map_.key_frames();
  LoopRecord record;
  record.kind = kind;
  record.from_key_frame = from;
  record.to_key_frame = to;
  record.from_stamp_ns = frames[from].stamp_ns;
  record.to_stamp_ns = frames[to].stamp_ns;
  record.outcome = outcome;
  record.correction = correction;
  loops_.push_back(record);
  return loops_.size() - 1;
}

void SlamPipeline::DropTentativeLoop() {
  tentative_loop_.reset();
  loops_[tentative_record_].outcome = LoopOutcome::kUnconfirmed;
}

void SlamPipeline::SettleLoopRecords() {
  for (LoopRecord& record : loops_) {
    if (record.outcome != LoopOutcome::kAccepted || record.kind == LoopKind::kLandmark) continue;
    const bool in_graph = std::any_of(edges_.begin(), edges_.end(),
                                      [&](const PoseGraphEdge& e) { return IsEdgeOf(e, record); });
    if (!in_graph) record.outcome = LoopOutcome::kRejectedAfterOptimisation;
  }
}

void TallyLoops(const std::vector<LoopRecord>& records, SlamQuality* quality) {
  SlamQuality& q = *quality;
  q.loop_candidates = q.loops_accepted = q.loops_rejected_match = 0;
  q.loops_rejected_disagreement = q.loops_rejected_degenerate = 0;
  q.loops_rejected_after_optimisation = q.loops_rejected_inconsistent = q.loops_confirmed = 0;
  q.landmark_loops_found = q.landmark_loops_accepted = q.landmark_loops_rejected = 0;
  q.camera_loops_found = q.camera_loops_accepted = q.camera_loops_rejected = 0;
  for (const LoopRecord& record : records) {
    const bool accepted = record.outcome == LoopOutcome::kAccepted;
    switch (record.kind) {
      case LoopKind::kScan:
        ++q.loop_candidates;
        if (record.confirmed) ++q.loops_confirmed;
        switch (record.outcome) {
          case LoopOutcome::kAccepted:
            ++q.loops_accepted;
            break;
          case LoopOutcome::kRejectedMatch:
          case LoopOutcome::kUnconfirmed:  // a match too weak to stand alone, never confirmed
          case LoopOutcome::kTentative:
            ++q.loops_rejected_match;
            break;
          case LoopOutcome::kRejectedDisagreement:
            ++q.loops_rejected_disagreement;
            break;
          case LoopOutcome::kRejectedDegenerate:
            ++q.loops_rejected_degenerate;
            break;
          case LoopOutcome::kRejectedAfterOptimisation:
            ++q.loops_rejected_after_optimisation;
            break;
          case LoopOutcome::kRejectedInconsistent:
            ++q.loops_rejected_inconsistent;
            break;
        }
        break;
      case LoopKind::kCamera:
        ++q.camera_loops_found;
        ++(accepted ? q.camera_loops_accepted : q.camera_loops_rejected);
        break;
      case LoopKind::kLandmark:
        ++q.landmark_loops_found;
        ++(accepted ? q.landmark_loops_accepted : q.landmark_loops_rejected);
        break;
    }
  }
}

bool SlamPipeline::ConfirmTentativeLoop(std::size_t key_frame) {
  if (!tentative_loop_) return false;
  const std::size_t tentative_key_frame = tentative_loop_->attempt.edge->to;
  if (key_frame <= tentative_key_frame) return false;  // only a later key frame confirms it
  if (key_frame > tentative_key_frame + options_.loops.confirm_within_key_frames) {
    DropTentativeLoop();
    return false;
  }
  LoopAttempt attempt = loop_closer_.Confirm(map_, key_frame, *tentative_loop_);
  HoldToGyro(&attempt);
  if (attempt.verdict != LoopVerdict::kAccepted) return false;
  loops_[tentative_record_].outcome = LoopOutcome::kAccepted;
  loops_[tentative_record_].confirmed = true;
  RecordScanLoop(attempt, key_frame, LoopOutcome::kAccepted);
  AddLoopEdge(tentative_loop_->attempt);
  AddLoopEdge(attempt);
  tentative_loop_.reset();
  Optimise();
  return true;
}

void SlamPipeline::HoldToGyro(LoopAttempt* attempt) const {
  if (attempt->edge && !GyroAgreesWithLoop(attempt->edge->from, attempt->edge->to,
                                           attempt->edge->T_from_to.theta_rad)) {
    attempt->verdict = LoopVerdict::kRejectedDisagreement;
    attempt->edge.reset();
  }
}

bool SlamPipeline::GyroTurnedBetween(std::size_t from, std::size_t to) const {
  const auto& frames = map_.key_frames();
  const ScanRecord& a = scans_[frames[from].scan_index];
  const ScanRecord& b = scans_[frames[to].scan_index];
  return a.T_odom_base && b.T_odom_base &&
         scans_without_gyro_[b.scan_index] == scans_without_gyro_[a.scan_index];
}

std::optional<double> SlamPipeline::GyroTurnRad(std::size_t from, std::size_t to) const {
  if (!GyroTurnedBetween(from, to)) return std::nullopt;
  const auto& frames = map_.key_frames();
  return scans_[frames[to].scan_index].T_odom_base->theta_rad -
         scans_[frames[from].scan_index].T_odom_base->theta_rad;
}

bool SlamPipeline::GyroAgreesWithLoop(std::size_t from, std::size_t to, double heading_rad) const {
  const std::optional<double> gyro_rad = GyroTurnRad(from, to);
  if (!gyro_rad) return true;
  const auto& frames = map_.key_frames();
  return std::abs(WrapAngle(heading_rad - *gyro_rad)) <=
         options_.loops.MaxGyroDisagreementRad(
             ToSeconds(frames[to].stamp_ns - frames[from].stamp_ns));
}

void SlamPipeline::AddLoopEdge(const LoopAttempt& attempt) {
  PoseGraphEdge edge = *attempt.edge;
  edge.information = EdgeInformation(attempt.match.information,
                                     map_.key_frames()[edge.from].T_world_base.theta_rad,
                                     options_.edge_sigma_floor_m, options_.edge_sigma_floor_rad);
  edges_.push_back(edge);
  unchecked_loops_.push_back(edges_.size() - 1);
  last_loop_key_frame_ = edge.to;
  any_loop_ = true;
}

void SlamPipeline::CloseCameraLoop(const TrackInput& input, const TrackStep& step) {
  const std::size_t key_frame = step.key_frame;
  if (last_camera_loop_key_frame_ &&
      key_frame < *last_camera_loop_key_frame_ + options_.loop_cooldown_key_frames) {
    return;
  }
  const std::optional<CameraLoop> loop = rgbd_->FindLoop(input, step, map_);
  if (!loop) return;
  const auto& frames = map_.key_frames();
  const double path_m = frames[key_frame].path_length_m - frames[loop->key_frame].path_length_m;
  const PlanarPose correction = Between(frames[key_frame].T_world_base, loop->T_world_base);
  const PlanarPose T_old_new = Between(frames[loop->key_frame].T_world_base, loop->T_world_base);
  if (std::hypot(correction.x_m, correction.y_m) > options_.loops.MaxCorrectionM(path_m) ||
      std::abs(correction.theta_rad) > options_.loops.MaxCorrectionRad(path_m) ||
      !GyroAgreesWithLoop(loop->key_frame, key_frame, T_old_new.theta_rad)) {
    RecordLoop(LoopKind::kCamera, loop->key_frame, key_frame, correction,
               LoopOutcome::kRejectedDisagreement);
    return;
  }
  RecordLoop(LoopKind::kCamera, loop->key_frame, key_frame, correction, LoopOutcome::kAccepted);
  PoseGraphEdge edge;
  edge.from = loop->key_frame;
  edge.to = key_frame;
  edge.T_from_to = T_old_new;
  edge.information =
      DiagonalInformation(options_.tracker.rgbd_sigma_m, options_.tracker.rgbd_sigma_rad);
  edge.loop = true;
  edge.camera = true;
  edges_.push_back(edge);
  unchecked_loops_.push_back(edges_.size() - 1);
  last_camera_loop_key_frame_ = key_frame;
  Optimise();
}

GraphReach SlamPipeline::ReachFrom(std::size_t key_frame) const {
  return OverEdgesAndLinks(edges_, landmark_links_, [&](const std::vector<PoseGraphEdge>& edges) {
    return reconstruct::ReachFrom(map_.key_frames().size(), edges, key_frame);
  });
}

std::vector<double> SlamPipeline::GraphDistancesFrom(std::size_t key_frame) const {
  return OverEdgesAndLinks(edges_, landmark_links_, [&](const std::vector<PoseGraphEdge>& edges) {
    return GraphDistances(map_.key_frames().size(), edges, key_frame);
  });
}

bool SlamPipeline::LandmarksInGraph() const {
  // Indoors (no IMU), before any landmark loop, the sightings repeat what the scan matches between
  // nearby key frames already hold (the same echoes, counted twice), and where a few bins and
  // pillars are the only round things that double count moved the trajectories at random. Outdoors
  // (an IMU: uneven ground) the scan matches slide along the terrain's echoes by a few per cent
  // over a long leg and jump where a root rocks the base; trunks and poles seen from several key
  // frames hold the leg from the start (only those whose radius is steady, and no sightings while
  // the base rocks: LandmarkMap::InGraph, landmark_max_rocking_rad). That takes a gyro's heading:
  // wheels alone slip by degrees over a root, and a trunk 5 m away is then taken for its neighbour
  // (park_tilts without the gyro: 0.6 m ATE laser only, 1.9 m with the sightings).
  return !landmark_links_.empty() || (options_.landmarks && tilted_ && gyro_heading_);
}

LandmarkTerms SlamPipeline::BuildLandmarkTerms(std::vector<std::size_t>* landmark_of_term) const {
  LandmarkTerms terms;
  if (!LandmarksInGraph() && !pending_landmark_loop_) return terms;
  const std::vector<Landmark>& landmarks = landmark_map_.landmarks();
  std::vector<std::size_t> compact(landmarks.size(), landmarks.size());
  for (std::size_t i = 0; i < landmarks.size(); ++i) {
    if (!landmark_map_.InGraph(landmarks[i])) continue;
    compact[i] = terms.positions.size();
    terms.positions.push_back(landmarks[i].position_world);
  }
  for (const LandmarkSighting& s : landmark_map_.sightings()) {
    if (compact[s.landmark] == landmarks.size()) continue;
    terms.terms.push_back({s.key_frame, compact[s.landmark], s.observation.centre_base,
                           s.observation.covariance_base});
    if (landmark_of_term != nullptr) landmark_of_term->push_back(s.landmark);
  }
  return terms;
}

void SlamPipeline::ApplyPoses(const std::vector<PlanarPose>& poses) {
  const PlanarPose T_new_old =
      Compose(poses.back(), Inverse(map_.key_frames().back().T_world_base));
  map_.SetPoses(poses);
  tracker_.OnKeyFramesMoved(T_new_old);
  landmark_map_.UpdatePositions(poses);
}

void SlamPipeline::CloseLandmarkLoops(std::size_t key_frame) {
  const KeyFrame& frame = map_.key_frames()[key_frame];
  if (frame.path_length_m - last_landmark_search_path_m_ < options_.landmark_loop_search_every_m) {
    // Between searches, sightings of old landmarks still pull the graph now and then.
    if (!LandmarksInGraph() || key_frame < last_landmark_optimised_key_frame_ +
                                               options_.landmark_optimise_every_key_frames) {
      return;
    }
    last_landmark_optimised_key_frame_ = key_frame;
    Optimise();
    return;
  }
  last_landmark_search_path_m_ = frame.path_length_m;
  const std::optional<LandmarkLoop> loop = landmark_map_.FindLoop(
      frame.T_world_base, frame.path_length_m, GraphDistancesFrom(key_frame));
  if (!loop) return;
  // The old key frame the link goes to: where the matched old landmarks were last seen.
  std::size_t old_key_frame = key_frame;
  for (const auto& [local, old] : loop->matches) {
    old_key_frame = std::min(old_key_frame, landmark_map_.landmarks()[old].last_key_frame);
  }
  const LandmarkMap before = landmark_map_;
  landmark_map_.Merge(*loop);
  std::vector<PlanarPose> poses = map_.Poses();
  std::vector<std::size_t> landmark_of_term;
  pending_landmark_loop_ = true;
  LandmarkTerms terms = BuildLandmarkTerms(&landmark_of_term);
  pending_landmark_loop_ = false;
  const PoseGraphResult result = OptimizePoseGraph(&poses, edges_, options_.graph, &terms);
  ++quality_.optimisations;
  // Verification: the merged landmarks' sightings must fit the optimised graph.
  double chi2_sum = 0;
  std::size_t chi2_count = 0;
  if (result.usable) {
    std::vector<bool> merged(landmark_map_.landmarks().size(), false);
    for (const auto& [local, old] : loop->matches) merged[old] = true;
    for (std::size_t t = 0; t < terms.terms.size(); ++t) {
      if (!merged[landmark_of_term[t]]) continue;
      const LandmarkTerm& term = terms.terms[t];
      chi2_sum += LandmarkChi2(poses[term.pose], terms.positions[term.landmark], term);
      ++chi2_count;
    }
  }
  const PlanarPose correction =
      result.usable ? Between(frame.T_world_base, poses[key_frame]) : PlanarPose{};
  if (!result.usable || chi2_count == 0 ||
      chi2_sum / static_cast<double>(chi2_count) > options_.max_landmark_loop_chi2) {
    landmark_map_ = before;
    RecordLoop(LoopKind::kLandmark, old_key_frame, key_frame, correction,
               LoopOutcome::kRejectedAfterOptimisation);
    return;
  }
  RecordLoop(LoopKind::kLandmark, old_key_frame, key_frame, correction, LoopOutcome::kAccepted);
  quality_.final_cost = result.final_cost;
  PoseGraphEdge link;
  link.from = old_key_frame;
  link.to = key_frame;
  link.T_from_to = Between(poses[old_key_frame], poses[key_frame]);
  link.information.setZero();
  link.loop = true;
  landmark_links_.push_back(link);
  last_landmark_optimised_key_frame_ = key_frame;
  ApplyPoses(poses);
}

void SlamPipeline::Optimise() {
  const std::vector<PlanarPose> before = map_.Poses();
  std::vector<PlanarPose> poses = before;
  LandmarkTerms terms = BuildLandmarkTerms();
  PoseGraphResult result = OptimizePoseGraph(&poses, edges_, options_.graph, &terms);
  ++quality_.optimisations;
  // Consistency after optimisation: a loop the graph cannot satisfy is taken out again, and the
  // graph optimised without it (false loops must not stay in).
  std::vector<std::size_t> unfit;  // SettleLoopRecords finds them gone
  for (std::size_t index : unchecked_loops_) {
    if (!result.usable || !LoopFits(edges_[index], poses, options_)) unfit.push_back(index);
  }
  unchecked_loops_.clear();
  if (!unfit.empty()) {
    EraseEdges(unfit);
    poses = before;
    terms = BuildLandmarkTerms();
    result = OptimizePoseGraph(&poses, edges_, options_.graph, &terms);
    ++quality_.optimisations;
  }
  if (!result.usable) return;
  quality_.final_cost = result.final_cost;
  ApplyPoses(poses);
}

void SlamPipeline::Finish() {
  // A survey ends back at its dock, turned to face the way it left: the likeliest loop of the run,
  // and one the wide searches, spaced by path, miss when the last stretch was short or a turn on
  // the spot.
  if (options_.loop_closure && map_.key_frames().size() > 1) {
    const std::size_t last = map_.key_frames().size() - 1;
    if (!any_loop_ || last_loop_key_frame_ != last) CloseLoops(last, true);
  }
  if (tentative_loop_) DropTentativeLoop();  // no key frame is left to confirm it
  if (!unchecked_loops_.empty() || LandmarksInGraph()) Optimise();
  if (DropInconsistentLoops()) Optimise();
  PruneFinalLoops();
  SettleLoopRecords();
  TallyLoops(loops_, &quality_);
  quality_.landmarks = landmark_map_.graph_landmarks();
  for (const LandmarkTerm& term : BuildLandmarkTerms().terms) {
    ++scans_[map_.key_frames()[term.pose].scan_index].landmark_sightings;
  }
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
  for (ScanRecord& record : scans_) {
    record.T_world_base = Compose(frames[record.key_frame].T_world_base, record.T_keyframe_base);
  }
  if (options_.refine_scans && quality_.alignment.rounds > 0) RefineScans();
  // The extent of the map first, so the grid is allocated once.
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    const PlanarPose T_world_laser = Compose(scans_[i].T_world_base, T_base_laser_);
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

bool SlamPipeline::DropInconsistentLoops() {
  const auto& frames = map_.key_frames();
  std::vector<double> path_length_m(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) path_length_m[i] = frames[i].path_length_m;
  // Each loop edge's accepted record, and its strength: the match's overlay (a camera loop's
  // alignment has none and counts as a full one).
  std::vector<LoopRecord*> record_of(edges_.size(), nullptr);
  std::vector<double> strength(edges_.size(), 1.0);
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    if (!edges_[i].loop) continue;
    for (LoopRecord& record : loops_) {
      if (record.outcome == LoopOutcome::kAccepted && IsEdgeOf(edges_[i], record)) {
        record_of[i] = &record;
        strength[i] = record.matching_ratio.value_or(1.0);
      }
    }
  }
  const std::vector<std::size_t> drop = InconsistentLoops(
      edges_, path_length_m, strength,
      [this](std::size_t a, std::size_t b) { return GyroTurnedBetween(a, b); },
      options_.loop_consistency);
  for (const std::size_t i : drop) {
    if (record_of[i]) record_of[i]->outcome = LoopOutcome::kRejectedInconsistent;
  }
  EraseEdges(drop);
  return !drop.empty();
}

void SlamPipeline::EraseEdges(const std::vector<std::size_t>& indices) {
  std::vector<bool> erase(edges_.size(), false);
  for (const std::size_t i : indices) erase[i] = true;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    if (!erase[i]) edges_[kept++] = std::move(edges_[i]);
  }
  edges_.resize(kept);
}

void SlamPipeline::PruneFinalLoops() {
  std::vector<PlanarPose> poses = map_.Poses();
  LandmarkTerms terms = BuildLandmarkTerms();
  const LoopPruning pruning =
      PruneLoops(&poses, &edges_, options_.max_final_loop_chi2, options_.graph, &terms);
  if (pruning.removed == 0) return;
  // Edges removed before an unusable solution stay removed; the poses are the last usable ones.
  quality_.optimisations += pruning.removed;
  if (pruning.usable) quality_.final_cost = pruning.final_cost;
  ApplyPoses(poses);
}

std::vector<PoseGraphEdge> SlamPipeline::KeyFrameOdometry() const {
  const auto& frames = map_.key_frames();
  std::vector<PoseGraphEdge> odometry(frames.size() > 0 ? frames.size() - 1 : 0);
  std::vector<bool> found(odometry.size(), false);
  for (const PoseGraphEdge& edge : edges_) {
    if (!IsTrackerStep(edge) || edge.to >= frames.size()) continue;
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
    edge.information =
        PredictionInformation(options_.tracker, edge.T_from_to, ToSeconds(b.stamp_ns - a.stamp_ns),
                              PredictionOf(b.odometry_used, b.heading_from_gyro));
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

void SlamPipeline::RefineScans() {
  std::vector<KeyFrame> frames(scans_.size());
  std::vector<PlanarPose> poses(scans_.size());
  std::vector<bool> held(scans_.size(), false);
  for (const KeyFrame& key_frame : map_.key_frames()) held[key_frame.scan_index] = true;
  std::vector<PoseGraphEdge> holds;
  const Eigen::Matrix3d hold =
      DiagonalInformation(options_.refine_hold_sigma_m, options_.refine_hold_sigma_rad);
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    KeyFrame& frame = frames[i];
    frame.scan_index = i;
    frame.stamp_ns = scans_[i].stamp_ns;
    frame.T_world_base = poses[i] = scans_[i].T_world_base;
    frame.points_base.reserve(map_points_base_[i].size());
    for (const MapPoint& point : map_points_base_[i]) {
      frame.points_base.emplace_back(point.x_cm / 100.0, point.y_cm / 100.0);
    }
    if (i > 0) holds.push_back({i - 1, i, Between(poses[i - 1], poses[i]), hold, false});
  }
  quality_.refinement = AlignScansToHeld(frames, holds, held, &poses, options_.alignment);
  if (quality_.refinement.rounds == 0) return;
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    ScanRecord& record = scans_[i];
    record.T_world_base = poses[i];
    record.T_keyframe_base =
        Between(map_.key_frames()[record.key_frame].T_world_base, record.T_world_base);
  }
}

std::vector<std::pair<TimestampNs, PlanarPose>> SlamPipeline::KeyFramePoses() const {
  std::vector<std::pair<TimestampNs, PlanarPose>> poses;
  for (const KeyFrame& k : map_.key_frames()) poses.emplace_back(k.stamp_ns, k.T_world_base);
  return poses;
}

}  // namespace littermap::reconstruct

#pragma once
// The 2D SLAM pipeline of `littermap reconstruct`, fed one scan at a time: tracking against the
// two-layer map (thesis 2.3, 2.5), a pose graph over key frames with loop closure, optimised with
// Ceres, and at the end an occupancy grid (thesis 2.1) rendered from the optimised poses.
// Bad input is handled and counted, never fatal: scans without a single valid echo, time going
// backwards, duplicate stamps, missing or implausible odometry.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "reconstruct/gyro_odometry.hpp"
#include "reconstruct/landmark_extraction.hpp"
#include "reconstruct/landmark_map.hpp"
#include "reconstruct/loop_closer.hpp"
#include "reconstruct/loop_consistency.hpp"
#include "reconstruct/loop_record.hpp"
#include "reconstruct/moving_echo_filter.hpp"
#include "reconstruct/occupancy_grid.hpp"
#include "reconstruct/pose_graph.hpp"
#include "reconstruct/scan_alignment.hpp"
#include "reconstruct/scan_points.hpp"
#include "reconstruct/terrain_relief.hpp"
#include "reconstruct/tilt_rocking.hpp"
#include "reconstruct/tracker.hpp"

namespace littermap::reconstruct {

// When the final scan alignment (AlignScans) runs. kAuto: for a level scanner only, i.e. unless
// an IMU reported the base's tilt. On uneven ground the scan plane cuts the terrain, and those
// echoes move with the robot; the tracker's fusion with the odometry holds them off, the dense
// alignment of key frames would not.
enum class AlignmentMode { kAuto, kOn, kOff };

struct SlamOptions {
  ScanPointsOptions points;
  double scan_voxel_size_m = 0.05;        // downsampling for matching
  MovingEchoFilterOptions moving_echoes;  // used with an IMU: the base's tilt and a gyro
  std::size_t min_scan_points = 20;       // fewer valid echoes: the scan is not matched
  TrackerOptions tracker;
  LoopCloserOptions loops;
  PoseGraphOptions graph;
  OccupancyGridOptions grid;
  double map_max_range_m = 30.0;  // echoes drawn into the occupancy grid; at most 300 m
  // Covariance floor of every matched edge (EdgeInformation). A match's own information counts
  // every echo as independent; without a gyro the edge's heading rests on the match alone, and a
  // laser matcher settles a little off at every key frame (edge_sigma_floor_rad). Where the gyro
  // turned every scan of the edge and the camera placed none, the tracker has fused a floored
  // match with the gyro's heading, whose drift its model states: only a small floor is added
  // (gyro_edge_sigma_floor_rad). An edge over scans the camera placed (the laser lost the map: a
  // tilt, an open lawn) took its path through poses the step's information does not speak for:
  // soft_edge_sigma_floor_rad, so that a loop's correction goes there rather than to the
  // stretches the laser held. (Scans placed by odometry alone are in the step's information: the
  // tracker fuses the key frame's match with the odometry since the last key frame.)
  double edge_sigma_floor_m = 0.02;
  double edge_sigma_floor_rad = 0.01;
  double gyro_edge_sigma_floor_rad = 0.002;
  double soft_edge_sigma_floor_rad = 0.02;
  // On hilly ground (where the moving-echo filter runs) the gyro's turn between consecutive key
  // frames is a heading-only edge of its own, its standard deviation growing with the square root
  // of the time between them (the gyro's angle random walk): the scan plane cuts the ground in arcs
  // that run along the path, which the filter cannot tell from walls, and the matches turn with
  // them by a tenth of a degree a second where the gyro does not. So is it over steps the camera
  // placed, on any ground: their soft floor is for the position the laser lost, and without the
  // gyro's edge a loop bent the heading there instead (park_tilts@102: 1.6 degrees in 5 s where
  // the gyro turned 0.03). 0: no such edges.
  double gyro_turn_sigma_rad_per_sqrt_s = 0.002;
  double odometry_sigma_m = 0.1;  // graph edge of an odometry-only key frame
  double odometry_sigma_rad = 0.05;
  bool loop_closure = true;
  std::size_t loop_cooldown_key_frames = 3;  // after an accepted loop
  // Landmarks (round obstacles) in the pose graph and loops closed on their constellations.
  bool landmarks = true;
  LandmarkExtractionOptions landmark_extraction;
  LandmarkMapOptions landmark_map;
  // No sightings from a scan whose tilt is further than this from the median tilt of the last
  // landmark_rocking_window_s (reconstruct/tilt_rocking.hpp).
  double landmark_max_rocking_rad = 0.05;
  double landmark_rocking_window_s = 2;
  double landmark_loop_search_every_m = 2;  // path between two constellation searches
  // After a constellation merge and optimisation, the merged landmarks' sightings must fit: their
  // mean chi-squared (2 degrees of freedom, 2 expected) at most this.
  double max_landmark_loop_chi2 = 6;
  // Once landmarks closed a loop, the graph is optimised this often (key frames) so the sightings
  // of old landmarks keep holding the trajectory between loops.
  std::size_t landmark_optimise_every_key_frames = 10;
  double wide_loop_search_every_m = 8;  // path between two wide loop searches
  // An optimised loop edge further than this from its measurement did not fit the graph.
  double max_loop_residual_m = 0.2;
  double max_loop_residual_rad = 0.05;
  // At the end, loops whose chi-squared in the optimised graph exceeds this are removed
  // (PruneLoops): the 95 % quantile with 3 degrees of freedom, the usual gate.
  double max_final_loop_chi2 = 7.81;
  // At the end, before that check, loops that tie the same two stretches of the path must agree
  // with each other (InconsistentLoops).
  LoopConsistencyOptions loop_consistency;
  AlignmentMode alignment_mode = AlignmentMode::kAuto;
  ScanAlignmentOptions alignment;
  // Once the key frames are aligned, every other scan is aligned the same way against them, held
  // where their alignment put them (AlignScansToHeld: the key frame before and after the scan and
  // those of other visits): a scan between two key frames then lies on the walls, not only where
  // the tracker's match against the local map left it. Each scan is held to its neighbour by its
  // tracked step with these sigmas (weak beside the walls: 0.02 to 1 m gave the same relation
  // errors, to 0.1 mm, on the raw CARMEN logs).
  bool refine_scans = true;
  double refine_hold_sigma_m = 0.05;
  double refine_hold_sigma_rad = 0.02;
  void Validate() const;
};

struct ScanRecord {
  std::size_t scan_index = 0;
  TimestampNs stamp_ns = 0;
  Routine routine = Routine::kOdometryOnly;
  double matching_ratio = 0;
  std::size_t key_frame = 0;
  PlanarPose T_keyframe_base;
  PlanarPose T_world_base;  // final, after optimisation
  double z_m = 0;           // height above where the run started, from the odometry (GyroOdometry)
  std::optional<PlanarPose> T_odom_base;  // the odometry used (gyro-turned), for comparisons
  bool odometry_used = false;      // the tracker predicted from the odometry since the last scan
  bool heading_from_gyro = false;  // and that odometry's turn is a gyro's
  // Landmark sightings of this scan's key frame that hold it in the final pose graph (range-
  // bearing factors; only scans that made a key frame, once landmarks closed a loop).
  std::size_t landmark_sightings = 0;
};

struct SlamQuality {
  std::size_t scans_in = 0;
  std::size_t scans_tracked = 0;
  std::size_t scans_without_echoes = 0;         // too few valid ranges (all max-range / NaN)
  std::size_t ground_echoes = 0;                // dropped as ground hits of a tilted scanner
  std::size_t scans_moving_echo_filtered = 0;   // scans the moving-echo filter ran on
  std::size_t moving_echoes = 0;                // dropped as moving with the robot
  std::size_t scans_moving_echoes = 0;          // given up: mostly moving echoes
  std::size_t stamps_backwards = 0;             // dropped
  std::size_t stamps_duplicate = 0;             // dropped
  std::size_t odometry_missing = 0;             // constant-velocity prediction used
  std::size_t odometry_rejected = 0;            // beyond its limits, or overruled by the laser
  std::size_t odometry_arbitrated = 0;          // the laser chose odometry or constant velocity
  std::array<std::size_t, 4> routine_counts{};  // indexed by Routine
  std::size_t key_frames = 0;
  // The loop counters below are the sums of the loop records (TallyLoops, at Finish).
  std::size_t loop_candidates = 0;
  std::size_t loops_accepted = 0;
  std::size_t loops_rejected_match = 0;
  std::size_t loops_rejected_disagreement = 0;
  std::size_t loops_rejected_degenerate = 0;  // the match left the pose free in some direction
  std::size_t loops_rejected_after_optimisation = 0;
  std::size_t loops_rejected_inconsistent = 0;  // disagreed with other loops (InconsistentLoops)
  // The five rejections above together.
  std::size_t loops_rejected() const {
    return loops_rejected_match + loops_rejected_disagreement + loops_rejected_degenerate +
           loops_rejected_after_optimisation + loops_rejected_inconsistent;
  }
  // Tentative matches the next key frames confirmed (LoopCloserOptions::
  // confirm_within_key_frames): each brings two accepted loops, itself and its confirmation.
  std::size_t loops_confirmed = 0;
  std::size_t optimisations = 0;
  double final_cost = 0;
  // Landmarks: in the graph (two sightings or more), sightings, sightings associated by tracking,
  // and loops closed on their constellations.
  std::size_t landmarks = 0;
  std::size_t landmark_sightings = 0;
  std::size_t landmark_associations = 0;
  std::size_t landmark_loops_found = 0;
  std::size_t landmark_loops_accepted = 0;
  std::size_t landmark_loops_rejected = 0;  // after optimisation: the merged sightings did not fit
  // Loops from camera frames aligned to RGB-D key frames long before (RgbdFallback::FindLoop):
  // rejected beyond the drift the path allows or when the optimised graph cannot satisfy them.
  std::size_t camera_loops_found = 0;
  std::size_t camera_loops_accepted = 0;
  std::size_t camera_loops_rejected = 0;
  ScanAlignmentResult alignment;   // the final scan alignment, if it ran
  ScanAlignmentResult refinement;  // of every scan (SlamOptions::refine_scans), if it ran
};

// Sets quality's loop counters from the run's loop records, kind by kind and outcome by
// outcome: the records are the one account of the loops, the counters their sums. A tentative
// record counts as a rejected match (it is one until confirmed).
void TallyLoops(const std::vector<LoopRecord>& records, SlamQuality* quality);

class SlamPipeline {
 public:
  SlamPipeline(const SlamOptions& options, const PlanarPose& T_base_laser,
               RgbdFallback* rgbd = nullptr);

  // odometry: at the scan's time, if any (wheels alone, or turned by a gyro: GyroOdometry);
  // tilt: the base's roll and pitch at the scan's time (IMU), if known.
  void AddScan(const LaserScan& scan, const std::optional<GyroOdometryPose>& odometry,
               const std::optional<Tilt>& tilt = std::nullopt);
  // Final optimisation; fills the scans' final poses and renders the map.
  void Finish();

  const std::vector<ScanRecord>& scans() const { return scans_; }
  std::vector<std::pair<TimestampNs, PlanarPose>> KeyFramePoses() const;
  const OccupancyGrid& map() const { return grid_; }
  const SlamQuality& quality() const { return quality_; }
  // The pose graph's edges: steps between consecutive key frames, the gyro's turns over them,
  // loops; after Finish, those of the final graph.
  const std::vector<PoseGraphEdge>& edges() const { return edges_; }
  // Every loop judged, in the order found; after Finish, each with its final outcome.
  const std::vector<LoopRecord>& loops() const { return loops_; }

 private:
  // echoes_filtered: the moving-echo filter ran on the key frame's scan (hilly ground).
  void AddGraphEdge(const TrackInput& input, const TrackStep& step, bool echoes_filtered);
  // end_of_run: the last key frame, where a survey is back at its dock: a wide search however
  // little path there was since the last one, whatever the cooldown.
  void CloseLoops(std::size_t key_frame, bool end_of_run = false);
  // Whether key frame `key_frame` confirms the tentative loop (then both are added).
  bool ConfirmTentativeLoop(std::size_t key_frame);
  // Adds an accepted loop edge to the graph (not yet optimised).
  void AddLoopEdge(const LoopAttempt& attempt);
  // The gyro turned every odometry step after key frame from's scan up to key frame to's.
  bool GyroTurnedBetween(std::size_t from, std::size_t to) const;
  // The gyro's turn from key frame `from` to `to` (odometry heading, unwrapped), where it turned
  // every step between them (GyroTurnedBetween); none otherwise.
  std::optional<double> GyroTurnRad(std::size_t from, std::size_t to) const;
  // False where a gyro turned the odometry all the way from `from` to `to` (key frames) and the
  // loop's heading between them disagrees with the gyro's turn
  // (LoopCloserOptions::MaxGyroDisagreementRad); true where there is no such gyro to ask.
  bool GyroAgreesWithLoop(std::size_t from, std::size_t to, double heading_rad) const;
  // A match the loop closer took (accepted or tentative) that the gyro contradicts
  // (GyroAgreesWithLoop) becomes a disagreement, like one beyond the drift bound.
  void HoldToGyro(LoopAttempt* attempt) const;
  // Records a scan-matched loop; returns its index in loops_.
  std::size_t RecordScanLoop(const LoopAttempt& attempt, std::size_t key_frame,
                             LoopOutcome outcome);
  std::size_t RecordLoop(LoopKind kind, std::size_t from, std::size_t to,
                         const PlanarPose& correction, LoopOutcome outcome);
  // The tentative loop was not confirmed in time: recorded as such.
  void DropTentativeLoop();
  // After the final pruning: a loop accepted then but no longer in the graph was rejected.
  void SettleLoopRecords();
  // Place recognition on the landmarks' constellation (LandmarkMap::FindLoop), verified by the
  // optimised graph.
  void CloseLandmarkLoops(std::size_t key_frame);
  // A loop from the camera frame at a new key frame to an old RGB-D key frame, checked against
  // the drift the path allows and then by the optimised graph like a scan-matched loop.
  void CloseCameraLoop(const TrackInput& input, const TrackStep& step);
  // The reach of the other key frames from one over the pose graph's edges and the landmark loops,
  // and their distances alone (the landmarks' place recognition needs no more).
  GraphReach ReachFrom(std::size_t key_frame) const;
  std::vector<double> GraphDistancesFrom(std::size_t key_frame) const;
  // Whether the landmarks' sightings hold the key frames in the pose graph (BuildLandmarkTerms).
  bool LandmarksInGraph() const;
  // The landmarks in the graph as Ceres terms, and the landmark each term's index maps from.
  LandmarkTerms BuildLandmarkTerms(std::vector<std::size_t>* landmark_of_term = nullptr) const;
  // Takes optimised key-frame poses: the map, the tracker and the landmarks follow.
  void ApplyPoses(const std::vector<PlanarPose>& poses);
  void Optimise();
  // Keeps a scan's echoes for the final map (map_points_base_).
  void StoreMapPoints(const Points2& points_base);
  // Drops the loops that disagree with other loops between the same stretches
  // (InconsistentLoops); whether any was dropped.
  bool DropInconsistentLoops();
  // Removes the edges at these indices of edges_, keeping the others in order.
  void EraseEdges(const std::vector<std::size_t>& indices);
  // The final check of the loops (PruneLoops), before the map is rendered.
  void PruneFinalLoops();
  // The final scan alignment (AlignScans), after the loops are settled.
  void AlignKeyFrames();
  // Relative-pose edges between consecutive key frames for the scan alignment: the odometry
  // where they are consecutive scans and the tracker took its increment (it is independent of
  // the laser, which the alignment brings in itself); otherwise the pose graph's edge, which
  // holds what the tracker matched in the scans between them, scans the alignment does not see.
  std::vector<PoseGraphEdge> KeyFrameOdometry() const;
  // Every scan aligned with the key frames held (SlamOptions::refine_scans); scans_' final poses
  // move.
  void RefineScans();

  SlamOptions options_;
  PlanarPose T_base_laser_;
  RgbdFallback* rgbd_ = nullptr;
  KeyFrameMap map_;
  Tracker tracker_;
  LoopCloser loop_closer_;
  LandmarkMap landmark_map_;
  // Links from a key frame to the one whose landmarks it recognised (for graph distances only:
  // the landmark terms carry the constraint).
  std::vector<PoseGraphEdge> landmark_links_;
  std::optional<TentativeLoop> tentative_loop_;  // a match awaiting its confirmation
  std::size_t tentative_record_ = 0;             // its index in loops_
  std::vector<LoopRecord> loops_;
  bool pending_landmark_loop_ = false;  // a landmark loop under verification
  double last_landmark_search_path_m_ = 0;
  std::size_t last_landmark_optimised_key_frame_ = 0;
  MovingEchoFilter moving_echoes_;
  TerrainRelief terrain_relief_;
  TiltRocking tilt_rocking_;
  OccupancyGrid grid_;
  std::vector<PoseGraphEdge> edges_;
  std::vector<std::size_t> unchecked_loops_;  // indices into edges_ since the last optimisation
  std::vector<ScanRecord> scans_;
  // Scans so far whose odometry the gyro did not turn (or without odometry), after each scan: a
  // stretch of scans was gyro-turned all along where it does not grow.
  std::vector<std::size_t> scans_without_gyro_;
  // Scans so far that the camera placed (routine rgbd), likewise.
  std::vector<std::size_t> scans_by_camera_;
  std::optional<double> first_odometry_z_m_;
  bool tilted_ = false;        // some scan came with the base's tilt
  bool gyro_heading_ = false;  // some scan's odometry turned with a gyro
  // Every scan's echoes for the map, one per map cell, within map_max_range_m, relative to the
  // base in whole centimetres: a 15-minute run at 40 Hz keeps 34 000 scans until the end (440 MB
  // at full resolution in double, 60 MB like this).
  struct MapPoint {
    std::int16_t x_cm = 0;
    std::int16_t y_cm = 0;
  };
  std::vector<std::vector<MapPoint>> map_points_base_;
  std::size_t last_loop_key_frame_ = 0;
  bool any_loop_ = false;
  std::optional<std::size_t> last_camera_loop_key_frame_;  // its own cooldown
  double last_wide_search_path_m_ = 0;  // path length at the last wide loop search
  std::optional<TimestampNs> last_stamp_ns_;
  SlamQuality quality_;
};

}  // namespace littermap::reconstruct

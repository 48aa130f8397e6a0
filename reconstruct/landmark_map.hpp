#pragma once
// The landmarks of a run (round obstacles, reconstruct/landmark_extraction.hpp) and their
// association, so that the pose graph can hold the key frames to the trunks they saw
// (pose-landmark range-bearing factors, reconstruct/pose_graph.hpp).
//
// Tracking: each key frame's circles are associated with the landmarks seen within the last
// stretch of path (active_path_m), nearest first, one to one, within a distance and a radius
// gate; a circle nothing claims starts a landmark. Older landmarks are never associated this
// way: after a long excursion the drift can exceed the gate, and an old trunk would be taken for
// the one next to it.
//
// Place recognition (loops): the constellation of the landmarks seen lately (their centres as
// the graph places them now, accurate relative to each other) is searched for among the old
// landmarks around the robot, independent of the view: every pair of local landmarks is
// compared with the pairs of old ones at the same distance (within pair_tolerance_m) and with
// matching radii; each match proposes a rigid transform, scored by how many local landmarks it
// puts on an old one (one to one, same radius). The best transform is refined on its inliers
// (least squares, 2D Umeyama without scale) and proposed only if it has enough inliers spread
// in two dimensions (a row of trees along a path fixes nothing along the row), clearly beats
// every other transform, and moves the robot by no more than the drift that can have
// accumulated along the graph since those landmarks were seen. The caller then merges the
// matched landmarks, optimises, and undoes the merge unless the merged landmarks' observations
// fit the optimised graph (false loops are rejected, never kept).

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/planar_pose.hpp"
#include "reconstruct/landmark_extraction.hpp"

namespace littermap::reconstruct {

struct LandmarkMapOptions {
  double association_gate_m = 0.3;
  double radius_gate_m = 0.08;
  double active_path_m = 20;
  std::size_t min_graph_observations = 2;  // a landmark enters the graph with this many
  // ... and if its fitted radius varies by at most this much (standard deviation over its
  // sightings): a trunk or a pole is the same circle from every side, a bush or a rock is not,
  // and its centre moves with the view.
  double max_graph_radius_spread_m = 0.015;
  // Place recognition.
  double local_path_m = 15;     // the constellation: landmarks seen within this much path
  double min_loop_path_m = 40;  // old landmarks: not seen within this much path
  double max_search_range_m = 40;
  double pair_tolerance_m = 0.15;
  double min_pair_distance_m = 2;
  double inlier_gate_m = 0.3;
  std::size_t min_inliers = 5;
  double min_inlier_spread_m = 1.5;   // standard deviation of the inliers along their thinner axis
  std::size_t min_inlier_margin = 2;  // over the best transform that differs
  double distinct_transform_m = 0.5;
  double distinct_transform_rad = 0.05;
  // Drift bound on the correction a loop implies: base + per metre of graph distance.
  double max_correction_m = 0.5;
  double max_correction_per_m = 0.03;
  double max_correction_rad = 0.05;
  double max_correction_rad_per_m = 0.002;
  void Validate() const;
};

struct Landmark {
  Eigen::Vector2d position_world = Eigen::Vector2d::Zero();
  double radius_m = 0;
  double radius_sq_sum_m2 = 0;  // over the sightings, for the radius's spread
  std::size_t observations = 0;
  double first_seen_path_m = 0;
  double last_seen_path_m = 0;
  std::size_t last_key_frame = 0;
  bool merged = false;  // absorbed into another landmark by a loop: no longer in use
};

// One key frame's sighting of a landmark.
struct LandmarkSighting {
  std::size_t key_frame = 0;
  std::size_t landmark = 0;
  LandmarkObservation observation;
};

// A constellation match: local landmark -> old landmark, and the transform that moves the
// graph's current estimate of the local landmarks onto the old ones.
struct LandmarkLoop {
  std::vector<std::pair<std::size_t, std::size_t>> matches;  // (local, old)
  PlanarPose T_old_local;
  std::size_t runner_up_inliers = 0;
};

class LandmarkMap {
 public:
  explicit LandmarkMap(const LandmarkMapOptions& options);

  // Associates a new key frame's circles (tracking, see above); returns how many were associated
  // with a landmark already known.
  std::size_t AddKeyFrame(std::size_t key_frame, const PlanarPose& T_world_keyframe, double path_m,
                          const std::vector<LandmarkObservation>& observations);
  // Place recognition around the key frame at T_world_current; graph_distance_m per key frame
  // (GraphDistances from the current one) for the drift bound.
  std::optional<LandmarkLoop> FindLoop(const PlanarPose& T_world_current, double path_m,
                                       const std::vector<double>& graph_distance_m) const;
  // Relabels the local landmarks' sightings as the old ones'.
  void Merge(const LandmarkLoop& loop);
  // Landmark positions from the key frames' poses (mean of their sightings).
  void UpdatePositions(const std::vector<PlanarPose>& key_frame_poses);

  const std::vector<Landmark>& landmarks() const { return landmarks_; }
  const std::vector<LandmarkSighting>& sightings() const { return sightings_; }
  // Whether a landmark holds the pose graph: in use, with at least min_graph_observations
  // sightings whose radii agree (max_graph_radius_spread_m).
  bool InGraph(const Landmark& landmark) const;
  std::size_t graph_landmarks() const;

 private:
  LandmarkMapOptions options_;
  std::vector<Landmark> landmarks_;
  std::vector<LandmarkSighting> sightings_;
};

}  // namespace littermap::reconstruct

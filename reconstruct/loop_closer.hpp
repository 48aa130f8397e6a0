#pragma once
// Loop closure over key frames (littermap's answer to the drift thesis 2.3 leaves open): a new
// key frame is matched against a submap of earlier key frames that lie within a search radius of
// it and far enough back along the path. Far along the pose graph from the current key frame (a
// long excursion, no loop in between) the drift can exceed what ICP's basin of attraction and the
// search radius cover, so a wide search also runs (at most every few metres): a correlative match
// over a window as large as the drift can be, against all earlier key frames within reach, refined
// by ICP. Such matches, and any loop to a key frame far along the graph, need a higher matching
// ratio: a wide window offers more places that only resemble the old one (a facade slid along
// itself, a row of trees); a weaker one may still become a loop once the next key frame confirms
// it (confirm_within_key_frames). Key frames placed by odometry alone widen the heading windows.
// A match becomes a loop edge only if it passes checks
// that reject false loops before they can be optimised in:
//   - ICP converged with a high matching ratio and a small residual;
//   - the match pins the pose down in every direction (not degenerate);
//   - the correction it implies agrees with the graph: no larger than the drift the tracker can
//     have accumulated over the path between the two key frames;
// and, after optimisation (in the caller), the loop edge must fit the optimised graph; at the end
// of the run every loop must still fit the final graph (PruneLoops).

#include <cstddef>
#include <optional>
#include <vector>

#include "reconstruct/correlative_matcher.hpp"
#include "reconstruct/icp_matcher.hpp"
#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/pose_graph.hpp"

namespace littermap::reconstruct {

struct LoopCloserOptions {
  IcpOptions icp;
  double search_radius_m = 6.0;
  double min_path_separation_m = 8.0;  // candidates must be this far back along the path
  std::size_t submap_half_window = 6;  // key frames each side of the candidate
  double min_matching_ratio = 0.6;
  double max_rms_residual_m = 0.05;
  // A match must pin the pose down in every direction: the standard deviation of its estimate
  // (the inverse of IcpResult::information) along its least constrained direction of
  // (x, y, heading x heading_lever_arm_m) at most this. The arc of one trunk, or a few, fits as
  // well turned about them: ICP then stops wherever its start put it, with a full overlay and a
  // small residual, and the loop would bend the graph by the tracker's drift or more (a false
  // loop at a park's dock, where the scan sees a trunk or two).
  double max_weakest_sigma_m = 0.05;
  double heading_lever_arm_m = 5;  // a heading error turns the points this far away by as much
  // Drift bound for the agreement check: base + per metre of path between the key frames.
  double max_correction_m = 0.4;
  double max_correction_per_m = 0.05;
  double max_correction_rad = 0.1;
  double max_correction_rad_per_m = 0.004;
  // Initial guesses around the estimate when the match from the estimate fails.
  double guess_step_m = 0.75;
  double guess_step_rad = 0.12;
  // The wide search: its window grows with the distance along the pose graph between the key
  // frames (the drift the tracker can have gathered between them), up to a limit.
  CorrelativeOptions correlative{.min_score = 0.4};  // mean likelihood of the scan on the old map
  double min_wide_window_m = 2;  // smaller drift: the nearest-candidate search covers it
  double wide_window_m = 0.5;
  double wide_window_per_m = 0.03;
  double max_wide_window_m = 15;
  double wide_window_rad = 0.05;
  double wide_window_rad_per_m = 0.0006;
  double max_wide_window_rad = 0.35;
  // Key frames placed by odometry alone (the scans did not match) drift the heading by up to this
  // many standard deviations of the odometry model over them: a few in a row can turn it more
  // than a long matched path, and the searches' heading windows widen for it.
  double odometry_drift_sigmas = 3;
  double min_wide_matching_ratio = 0.85;  // for wide matches and far candidates
  // A match that overlays less than min_wide_matching_ratio of the scan but at least
  // min_matching_ratio is tentative where that evidence alone is too weak but the loop is likely
  // real: a loop only if one of the next few key frames, put where its correction says, matches
  // the old map there too (min_matching_ratio, ICP from that pose) and ICP moves it no further
  // than these. That is
  //   - a far candidate of the nearest-candidate search: a street driven again after a long
  //     excursion, whose open view overlays 60-85 % of the scan (the search starts from the
  //     estimate, so the correction stays within its guesses);
  //   - a wide match after a stretch where the scans did not match and odometry alone turned the
  //     heading by more than the matched path can have (OdometryHeadingRad > MatchedHeadingRad):
  //     the drift is beyond the nearest-candidate search.
  // Other wide matches that weak are rejected: over a window of metres, in a corridor, the next
  // key frame slides along the same walls as the match, so its agreement proves nothing.
  std::size_t confirm_within_key_frames = 6;
  double max_confirmation_disagreement_m = 0.3;
  double max_confirmation_disagreement_rad = 0.05;
  double far_graph_distance_m = 300;  // a candidate this far along the graph is "far"
  // A key frame with fewer points than this (a few trunks in a park) is matched together with
  // the key frames just before it, up to this far back along the path: their relative poses
  // are accurate, and together they pin the pose down where one sparse scan cannot.
  std::size_t min_source_points = 150;
  double max_source_path_m = 5;
  double source_voxel_size_m = 0.05;
  // The drift bound over path_m of path between two key frames: a loop whose correction is
  // larger in position or heading is not explained by drift.
  double MaxCorrectionM(double path_m) const {
    return max_correction_m + max_correction_per_m * path_m;
  }
  double MaxCorrectionRad(double path_m) const {
    return max_correction_rad + max_correction_rad_per_m * path_m;
  }
  // Where a gyro turned the odometry all the way between the two key frames, a loop's heading
  // between them must agree with the gyro's turn to within this floor plus this much per second
  // between them: a gyro's bias (0.0002 rad/s is 41 degrees an hour, an uncalibrated MEMS gyro's)
  // turns its heading with time, not with the path. The floor is twice the heading a gyro's
  // angle random walk (0.002 rad/sqrt(s)) gathers over a minute. The path-based bound above allows
  // a park survey's dock loop 47 degrees; the gyro, a few.
  double max_gyro_disagreement_rad = 0.03;
  double max_gyro_disagreement_rad_per_s = 0.0002;
  double MaxGyroDisagreementRad(double elapsed_s) const {
    return max_gyro_disagreement_rad + max_gyro_disagreement_rad_per_s * elapsed_s;
  }
  void Validate() const;
};

// Where the earlier key frames are from the current one over the pose graph: the distance along
// it, and the variance its key frames placed by odometry alone add to the heading on the way (the
// least over the paths; PoseGraphEdge::odometry_sigma_rad). The searches' windows grow with both.
// Empty: along the path, without loops or key frames placed by odometry.
struct GraphReach {
  std::vector<double> distance_m;
  std::vector<double> odometry_heading_variance_rad2;
};

// The reach of every key frame from `current` over these edges.
GraphReach ReachFrom(std::size_t key_frames, const std::vector<PoseGraphEdge>& edges,
                     std::size_t current);

enum class LoopVerdict {
  kNoCandidate,
  kAccepted,
  kRejectedMatch,
  kRejectedDisagreement,
  kRejectedDegenerate,  // the match leaves the pose free in some direction
  kTentative            // a match awaiting its confirmation (LoopCloser::Confirm)
};

struct LoopAttempt {
  LoopVerdict verdict = LoopVerdict::kNoCandidate;
  std::size_t candidate = 0;  // the earlier key frame
  IcpResult match;
  std::optional<PoseGraphEdge> edge;  // set when accepted or tentative
  PlanarPose window;                  // the half-widths the search covered (x, y, heading)
  // Of the match, once it passed the ratio and residual checks (max_weakest_sigma_m).
  std::optional<double> weakest_sigma_m;
};

// A tentative loop: key frame edge->to, corrected to T_world_corrected.
struct TentativeLoop {
  LoopAttempt attempt;
  PlanarPose T_world_corrected;
};

class LoopCloser {
 public:
  explicit LoopCloser(const LoopCloserOptions& options);
  // Tries to close a loop from key frame `current` to an earlier key frame; with `wide` the wide
  // search too.
  LoopAttempt TryClose(const KeyFrameMap& map, std::size_t current, const GraphReach& reach = {},
                       bool wide = false) const;
  // Whether key frame `current` confirms a tentative loop of an earlier key frame: the attempt
  // for its own edge, accepted if it does (then the tentative edge is a loop too).
  LoopAttempt Confirm(const KeyFrameMap& map, std::size_t current,
                      const TentativeLoop& tentative) const;

 private:
  // Matches key frame `current` against the submap around `candidate` and applies the checks.
  // The initial guesses cover heading_rad either side of the estimate.
  LoopAttempt TryCandidate(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                           double min_ratio, double heading_rad) const;
  // The old map around `candidate` that key frame `current` is matched against: the key frames
  // either side of it, stopping short of the recent path.
  MapPoints CandidateSubmap(const KeyFrameMap& map, std::size_t current,
                            std::size_t candidate) const;
  // The earlier key frames far enough back along the path from `current` and within radius_m of
  // `position`.
  std::vector<std::size_t> Within(const KeyFrameMap& map, std::size_t current,
                                  const PlanarPose& position, double radius_m) const;
  // The points matched for key frame `current`, in its base frame (see min_source_points).
  Points2 SourcePoints(const KeyFrameMap& map, std::size_t current) const;
  // The wide search around key frame `current`.
  LoopAttempt TryWide(const KeyFrameMap& map, std::size_t current, const GraphReach& reach) const;
  // Matches against the submap around the earlier key frame nearest to `current`.
  LoopAttempt TryNearest(const KeyFrameMap& map, std::size_t current,
                         const GraphReach& reach) const;
  // The heading drift between key frame j and `current` that their matched path explains (the
  // wide search's window for its length), and the drift that key frames placed by odometry alone
  // on the way add.
  double MatchedHeadingRad(const KeyFrameMap& map, std::size_t current, std::size_t j,
                           const GraphReach& reach) const;
  double OdometryHeadingRad(std::size_t j, const GraphReach& reach) const;
  // The heading window (half-width) over which key frame j can have drifted from `current`.
  double HeadingWindowRad(const KeyFrameMap& map, std::size_t current, std::size_t j,
                          const GraphReach& reach) const;
  // The verdict on a match of key frame `current` that an edge from `candidate` would carry;
  // `window`: the half-widths a wide search covered (zero for the nearest-candidate search).
  LoopAttempt Judge(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                    const IcpResult& match, double min_ratio, const PlanarPose& window) const;

  LoopCloserOptions options_;
};

}  // namespace littermap::reconstruct

#pragma once
// Loop closure over key frames (littermap's answer to the drift thesis 2.3 leaves open): a new
// key frame is matched against a submap of earlier key frames that lie within a search radius of
// it and far enough back along the path. Far along the pose graph from the current key frame (a
// long excursion, no loop in between) the drift can exceed what ICP's basin of attraction and the
// search radius cover, so a wide search also runs (at most every few metres): a correlative match
// over a window as large as the drift can be, against all earlier key frames within reach, refined
// by ICP. Such matches, and any loop to a key frame far along the graph, need a higher matching
// ratio: a wide window offers more places that only resemble the old one (a facade slid along
// itself, a row of trees). A match becomes a loop edge only if it passes checks
// that reject false loops before they can be optimised in:
//   - ICP converged with a high matching ratio and a small residual;
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
  CorrelativeOptions correlative;
  double min_wide_window_m = 2;  // smaller drift: the nearest-candidate search covers it
  double wide_window_m = 0.5;
  double wide_window_per_m = 0.03;
  double max_wide_window_m = 15;
  double wide_window_rad = 0.05;
  double wide_window_rad_per_m = 0.0006;
  double max_wide_window_rad = 0.35;
  double min_correlative_score = 0.4;     // mean likelihood of the scan on the old map
  double min_wide_matching_ratio = 0.85;  // for wide matches and far candidates
  double far_graph_distance_m = 300;      // a candidate this far along the graph is "far"
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
  void Validate() const;
};

enum class LoopVerdict { kNoCandidate, kAccepted, kRejectedMatch, kRejectedDisagreement };

struct LoopAttempt {
  LoopVerdict verdict = LoopVerdict::kNoCandidate;
  std::size_t candidate = 0;  // the earlier key frame
  IcpResult match;
  std::optional<PoseGraphEdge> edge;  // set when accepted
};

class LoopCloser {
 public:
  explicit LoopCloser(const LoopCloserOptions& options);
  // Tries to close a loop from key frame `current` to an earlier key frame; with `wide` the wide
  // search too. graph_distance_m: per key frame, its distance from `current` along the pose
  // graph; empty means along the path (no loops yet).
  LoopAttempt TryClose(const KeyFrameMap& map, std::size_t current,
                       const std::vector<double>& graph_distance_m = {}, bool wide = false) const;

 private:
  // Matches key frame `current` against the submap around `candidate` and applies the checks.
  LoopAttempt TryCandidate(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                           double min_ratio) const;
  // The points matched for key frame `current`, in its base frame (see min_source_points).
  Points2 SourcePoints(const KeyFrameMap& map, std::size_t current) const;
  // The wide search around key frame `current`.
  LoopAttempt TryWide(const KeyFrameMap& map, std::size_t current,
                      const std::vector<double>& graph_distance_m) const;
  // Matches against the submap around the earlier key frame nearest to `current`.
  LoopAttempt TryNearest(const KeyFrameMap& map, std::size_t current,
                         const std::vector<double>& graph_distance_m) const;
  // The verdict on a match of key frame `current` that an edge from `candidate` would carry;
  // `window`: the half-widths a wide search covered (zero for the nearest-candidate search).
  LoopAttempt Judge(const KeyFrameMap& map, std::size_t current, std::size_t candidate,
                    const IcpResult& match, double min_ratio, const PlanarPose& window) const;

  LoopCloserOptions options_;
};

}  // namespace littermap::reconstruct

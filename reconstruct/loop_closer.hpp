#pragma once
// Loop closure over key frames (littermap's answer to the drift thesis 2.3 leaves open): a new
// key frame is matched against a submap of earlier key frames that lie within a search radius of
// it and far enough back along the path. A match becomes a loop edge only if it passes checks
// that reject false loops before they can be optimised in:
//   - ICP converged with a high matching ratio and a small residual;
//   - the correction it implies agrees with the graph: no larger than the drift the tracker can
//     have accumulated over the path between the two key frames;
// and, after optimisation (in the caller), the loop edge must fit the optimised graph.

#include <cstddef>
#include <optional>

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
  // Tries to close a loop from key frame `current` to an earlier key frame.
  LoopAttempt TryClose(const KeyFrameMap& map, std::size_t current) const;
  // Matches key frame `current` against the submap around `candidate` and applies the checks.
  LoopAttempt TryCandidate(const KeyFrameMap& map, std::size_t current,
                           std::size_t candidate) const;

 private:
  LoopCloserOptions options_;
};

}  // namespace littermap::reconstruct

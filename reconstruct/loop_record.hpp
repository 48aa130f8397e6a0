#pragma once
// The record of one loop the pipeline judged: which key frames it joins, how it was found, and
// what became of it, with the evidence of its match. A run writes them as loops.csv, so a bent
// map can be traced to the loop that bent it.

#include <cstddef>
#include <optional>
#include <string_view>

#include "core/planar_pose.hpp"
#include "core/time.hpp"

namespace littermap::reconstruct {

enum class LoopKind {
  kScan,      // scan matching against old key frames (LoopCloser)
  kCamera,    // a camera frame aligned to an old RGB-D key frame
  kLandmark,  // the constellation of landmarks recognised (LandmarkMap::FindLoop)
};

enum class LoopOutcome {
  kAccepted,                   // in the final pose graph
  kRejectedMatch,              // the match was too weak
  kRejectedDisagreement,       // its correction is more than the drift can explain
  kRejectedDegenerate,         // the match left the pose free in some direction
  kRejectedAfterOptimisation,  // the optimised graph could not satisfy it
  kRejectedInconsistent,       // it disagreed with other loops between the same stretches
  kUnconfirmed,                // tentative, and no later key frame confirmed it
  kTentative,                  // awaiting its confirmation (never in a finished run's record)
};

struct LoopRecord {
  LoopKind kind = LoopKind::kScan;
  std::size_t from_key_frame = 0;  // the earlier key frame
  std::size_t to_key_frame = 0;
  TimestampNs from_stamp_ns = 0;
  TimestampNs to_stamp_ns = 0;
  LoopOutcome outcome = LoopOutcome::kRejectedMatch;
  bool confirmed = false;  // a tentative match a later key frame confirmed
  // The move the loop asked of the later key frame, in its own frame (zero when no match).
  PlanarPose correction;
  std::optional<double> matching_ratio;   // scan matches
  std::optional<double> weakest_sigma_m;  // scan matches: LoopCloserOptions::max_weakest_sigma_m
};

constexpr std::string_view LoopKindName(LoopKind kind) {
  switch (kind) {
    case LoopKind::kScan:
      return "scan";
    case LoopKind::kCamera:
      return "camera";
    case LoopKind::kLandmark:
      return "landmark";
  }
  return "scan";
}

constexpr std::string_view LoopOutcomeName(LoopOutcome outcome) {
  switch (outcome) {
    case LoopOutcome::kAccepted:
      return "accepted";
    case LoopOutcome::kRejectedMatch:
      return "rejected_match";
    case LoopOutcome::kRejectedDisagreement:
      return "rejected_disagreement";
    case LoopOutcome::kRejectedDegenerate:
      return "rejected_degenerate";
    case LoopOutcome::kRejectedAfterOptimisation:
      return "rejected_after_optimisation";
    case LoopOutcome::kRejectedInconsistent:
      return "rejected_inconsistent";
    case LoopOutcome::kUnconfirmed:
      return "unconfirmed";
    case LoopOutcome::kTentative:
      return "tentative";
  }
  return "rejected_match";
}

}  // namespace littermap::reconstruct

#pragma once
// Loops that tie the same two stretches of a survey must agree with each other. Coming home to
// a park's dock, the first match against the dock's key frame sees the same trunks from another
// side: their arcs are other parts of the trunks, and ICP can settle 0.13-0.20 m and 2 degrees
// off with a full overlay. The loops a few metres later, nearer the dock, are right to 2 cm;
// the graph then bends between them to fit both (the stretch the camera placed is soft), so no
// chi-squared check on the optimised graph sees the wrong one. Between two loops whose earlier
// ends and later ends lie close along the path, the tracker's relative poses close a cycle:
// loop, stretch, loop back, stretch. Where the cycle does not close, one of the two is wrong, and
// the one that disagrees with more loops, else the weaker match, is dropped. The bounds are for
// a tracker whose heading a gyro holds: a laser alone turns more over a stretch (on
// freiburg-campus, where no gyro is, the check took out loops that held the map), so loops are
// compared only over stretches a gyro held.

#include <cstddef>
#include <functional>
#include <vector>

#include "reconstruct/pose_graph.hpp"

namespace littermap::reconstruct {

struct LoopConsistencyOptions {
  // Two loops are compared when their earlier ends, and their later ends, each lie within this
  // much path of each other (over such stretches the tracker's relative poses are accurate).
  double max_stretch_m = 15;
  // How far the cycle of two true loops may miss: each loop's own error (true loops' matches are
  // within 2-3 cm and 0.4 degrees of the truth on the simulated parks), plus the tracker's drift
  // over the two stretches, per metre of them.
  double max_disagreement_m = 0.06;
  double max_disagreement_per_m = 0.01;
  double max_disagreement_rad = 0.015;
  double max_disagreement_rad_per_m = 0.001;
  void Validate() const;
};

// The loop edges to drop, as indices into edges, in the order they were dropped. path_length_m:
// each pose's distance along the path; strength: per edge, how much its match is trusted (the
// matching ratio; ignored for edges that are not loops). The stretches between loop ends are
// composed from the sequential edges (from i to i + 1, not loops, not heading-only); loops
// whose stretches have a gap are not compared. While any two remaining loops disagree, the loop
// with the most disagreements is dropped; among equals, the weakest. held(a, b): whether a gyro
// held the tracker's heading all the way between poses a < b; other stretches are no evidence.
std::vector<std::size_t> InconsistentLoops(
    const std::vector<PoseGraphEdge>& edges, const std::vector<double>& path_length_m,
    const std::vector<double>& strength, const std::function<bool(std::size_t, std::size_t)>& held,
    const LoopConsistencyOptions& options);

}  // namespace littermap::reconstruct

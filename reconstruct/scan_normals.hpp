#pragma once
// Line normals of a scan's points from their neighbours along the scan. A laser's echoes come in
// beam order, and a neighbour belongs to the same surface while the gap to it grows no faster
// than the beams spread apart with range: the sparse echoes of a far wall still lie on a line,
// and a depth jump ends it. Nearest neighbours within a fixed radius, by contrast, leave far
// walls without normals.
//
// A point on no line (a post, a corner) can still be matched point to point if it samples its
// surface finely, that is, if a neighbour along the scan lies within the same gap. The sparse
// echoes of a wall seen at a grazing angle do not: matched point to point, each would pull
// towards wherever the few samples of the other scan happen to lie, and along a corridor that
// holds a pose where it was instead of where the odometry puts it.

#include <cstddef>
#include <vector>

#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

struct ScanNormalsOptions {
  std::size_t neighbours_per_side = 2;
  // Largest gap between neighbours: the larger of a floor and a share of the range.
  double min_gap_m = 0.15;
  double gap_per_m = 0.05;
  void Validate() const;
};

struct ScanNormals {
  Points2 normals;  // unit, facing the sensor at the origin; zero where no line fits
  // Per point: it may be matched at all (on a line, or with a neighbour within the gap).
  std::vector<bool> matchable;
};

// points: in the sensor's (or base's) frame, in the scan's order.
ScanNormals EstimateScanNormals(const Points2& points, const ScanNormalsOptions& options);

}  // namespace littermap::reconstruct

#include "reconstruct/scan_normals.hpp"

#include <algorithm>
#include <cstdint>

#include "core/error.hpp"
#include "reconstruct/icp_matcher.hpp"

namespace littermap::reconstruct {

void ScanNormalsOptions::Validate() const {
  if (neighbours_per_side < 1) throw UsageError("scan normals: neighbours_per_side must be >= 1");
  if (!(min_gap_m > 0) || !(gap_per_m >= 0)) {
    throw UsageError("scan normals: min_gap_m must be > 0 and gap_per_m >= 0");
  }
}

ScanNormals EstimateScanNormals(const Points2& points, const ScanNormalsOptions& options) {
  options.Validate();
  ScanNormals result;
  result.normals.assign(points.size(), Eigen::Vector2d::Zero());
  result.matchable.assign(points.size(), false);
  std::vector<std::uint32_t> neighbourhood;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // The gap allowed at this point's range, between each two neighbours on the way out.
    const double gap_m = std::max(options.min_gap_m, options.gap_per_m * points[i].norm());
    const auto adjacent = [&](std::size_t a, std::size_t b) {
      return (points[a] - points[b]).norm() <= gap_m;
    };
    neighbourhood.assign(1, static_cast<std::uint32_t>(i));
    for (std::size_t j = i; j > 0 && i - j < options.neighbours_per_side && adjacent(j - 1, j);
         --j) {
      neighbourhood.push_back(static_cast<std::uint32_t>(j - 1));
    }
    for (std::size_t j = i;
         j + 1 < points.size() && j - i < options.neighbours_per_side && adjacent(j, j + 1); ++j) {
      neighbourhood.push_back(static_cast<std::uint32_t>(j + 1));
    }
    Eigen::Vector2d n = LineNormal(points, neighbourhood);
    if (n.dot(points[i]) > 0) n = -n;
    result.normals[i] = n;
    result.matchable[i] = n.squaredNorm() > 0.5 || neighbourhood.size() > 1;
  }
  return result;
}

}  // namespace littermap::reconstruct

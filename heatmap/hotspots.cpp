#include "heatmap/hotspots.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include <opencv2/imgproc.hpp>

namespace littermap::heatmap {
namespace {

bool IsLocalMaximum(const Raster& density, int column, int row, int radius, float nodata) {
  const float value = density.at(column, row);
  const GridGeometry& grid = density.grid;
  for (int r = std::max(0, row - radius); r <= std::min(grid.height - 1, row + radius); ++r) {
    for (int c = std::max(0, column - radius); c <= std::min(grid.width - 1, column + radius);
         ++c) {
      const float other = density.at(c, r);
      if (other == nodata) continue;
      // Ties go to the first cell in row-major order, so a plateau yields one peak.
      if (other > value || (other == value && (r < row || (r == row && c < column)))) return false;
    }
  }
  return true;
}

struct Peak {
  db::PointXY crs;
  double density_per_100m2 = 0.0;
};

double Distance(const db::PointXY& a, const db::PointXY& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// Peaks joined when their kernels overlap, through any chain of peaks (union-find).
std::vector<std::vector<std::size_t>> MergeOverlapping(const std::vector<Peak>& peaks,
                                                       double reach_m) {
  std::vector<std::size_t> parent(peaks.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    for (std::size_t j = i + 1; j < peaks.size(); ++j) {
      if (Distance(peaks[i].crs, peaks[j].crs) < 2 * reach_m) {
        parent[std::max(root(i), root(j))] = std::min(root(i), root(j));
      }
    }
  }
  std::vector<std::vector<std::size_t>> areas;
  std::vector<long> area_of(peaks.size(), -1);
  for (std::size_t i = 0; i < peaks.size(); ++i) {  // densest first: the area's first peak
    const std::size_t r = root(i);
    if (area_of[r] < 0) {
      area_of[r] = static_cast<long>(areas.size());
      areas.emplace_back();
    }
    areas[static_cast<std::size_t>(area_of[r])].push_back(i);
  }
  return areas;
}

std::vector<db::PointXY> Outline(const std::vector<db::PointXY>& peaks, double radius_m) {
  constexpr int kSides = 24;
  // Relative to the first peak: cv::convexHull works in float, too coarse for UTM coordinates.
  const db::PointXY origin = peaks.front();
  std::vector<cv::Point2f> points;
  for (const db::PointXY& p : peaks) {
    for (int k = 0; k < kSides; ++k) {
      const double angle = 2 * std::numbers::pi * k / kSides;
      points.emplace_back(static_cast<float>(p.x - origin.x + radius_m * std::cos(angle)),
                          static_cast<float>(p.y - origin.y + radius_m * std::sin(angle)));
    }
  }
  std::vector<cv::Point2f> hull;
  cv::convexHull(points, hull, /*clockwise=*/false);
  std::vector<db::PointXY> outline;
  for (const cv::Point2f& p : hull) outline.push_back({origin.x + p.x, origin.y + p.y});
  return outline;
}

}  // namespace

int Hotspot::items_nearby() const {
  int items = 0;
  for (const auto& [name, count] : items_by_class) items += count;
  return items;
}

double HotspotMinSurveys(std::size_t runs) { return runs >= 2 ? 2.0 : 1.0; }

std::vector<Hotspot> FindHotspots(const Raster& all_density, float nodata,
                                  std::span<const ClassifiedPoint> items,
                                  const HotspotOptions& options, const Raster* effort) {
  // Ground surveyed too rarely takes no part: at the fringe of the runs' coverage one survey's
  // find is a high density by chance, and the peaks would sit there.
  Raster well_surveyed;
  if (effort != nullptr) {
    well_surveyed = all_density;
    for (int r = 0; r < well_surveyed.grid.height; ++r) {
      for (int c = 0; c < well_surveyed.grid.width; ++c) {
        if (effort->at(c, r) < options.min_effort_surveys) well_surveyed.at(c, r) = nodata;
      }
    }
  }
  const Raster& density = effort != nullptr ? well_surveyed : all_density;
  const GridGeometry& grid = density.grid;
  const int radius =
      std::max(1, static_cast<int>(std::ceil(options.separation_m / grid.cell_size_m)));
  std::vector<Peak> peaks;
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const float value = density.at(c, r);
      if (value == nodata || value <= 0.0f || value < options.min_density_per_100m2) continue;
      if (!IsLocalMaximum(density, c, r, radius, nodata)) continue;
      peaks.push_back({{grid.CellCenterX(c), grid.CellCenterY(r)}, value});
    }
  }
  // An item found where the runs rarely looked is no support either.
  const auto WellSurveyed = [&](const db::PointXY& crs) {
    if (effort == nullptr) return true;
    const int c = static_cast<int>(std::floor((crs.x - grid.min_x_m) / grid.cell_size_m));
    const int r = static_cast<int>(std::floor((grid.max_y_m - crs.y) / grid.cell_size_m));
    if (c < 0 || r < 0 || c >= grid.width || r >= grid.height) return false;
    return effort->at(c, r) >= options.min_effort_surveys;
  };
  std::stable_sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) {
    return a.density_per_100m2 > b.density_per_100m2;
  });

  std::vector<Hotspot> hotspots;
  if (options.max_count <= 0) return hotspots;
  for (const std::vector<std::size_t>& area : MergeOverlapping(peaks, options.separation_m)) {
    const Peak& densest = peaks[area.front()];
    Hotspot hotspot;
    hotspot.crs = densest.crs;
    hotspot.density_per_100m2 = densest.density_per_100m2;
    for (const std::size_t i : area) hotspot.peaks.push_back(peaks[i].crs);
    for (const ClassifiedPoint& item : items) {
      const bool near = std::any_of(hotspot.peaks.begin(), hotspot.peaks.end(), [&](auto& p) {
        return Distance(item.crs, p) <= options.separation_m;
      });
      if (!near || !WellSurveyed(item.crs)) continue;
      ++hotspot.items_by_class[item.class_name];
    }
    if (hotspot.items_nearby() < options.min_items) continue;
    int best = 0;
    for (const auto& [name, count] : hotspot.items_by_class) {
      if (count > best) {
        best = count;
        hotspot.dominant_class = name;
      }
    }
    hotspot.outline = Outline(hotspot.peaks, options.separation_m);
    hotspots.push_back(std::move(hotspot));
    if (static_cast<int>(hotspots.size()) == options.max_count) break;
  }
  for (std::size_t i = 0; i < hotspots.size(); ++i) hotspots[i].rank = static_cast<int>(i) + 1;
  return hotspots;
}

}  // namespace littermap::heatmap

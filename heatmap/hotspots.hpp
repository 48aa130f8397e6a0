#pragma once
// Hotspots for crews: places to clean, not statistical peaks. Local maxima of the density raster
// whose kernels overlap (closer than two bandwidths) are one area; an area counts as a hotspot
// only with enough support, distinct items near it and ground surveyed often enough that its
// density is not one survey's chance; hotspots are ranked by their densest point, each with the
// class most of its items have and its outline (the hull of its peaks' kernels).

#include <map>
#include <span>
#include <string>
#include <vector>

#include "db/geometry_blob.hpp"
#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct HotspotOptions {
  double separation_m = 3.0;           // the kernel bandwidth: a peak's reach
  double min_density_per_100m2 = 0.0;  // a peak must exceed this
  int max_count = 20;
  int min_items = 3;                // distinct items within separation_m of the area's peaks
  double min_effort_surveys = 1.0;  // with an effort raster: cells surveyed less are left out
};

struct Hotspot {
  int rank = 0;     // 1 = densest
  db::PointXY crs;  // the densest point
  double density_per_100m2 = 0.0;
  std::string dominant_class;
  std::map<std::string, int> items_by_class;  // distinct items of the area, by class
  std::vector<db::PointXY> peaks;             // the merged maxima, densest first
  std::vector<db::PointXY> outline;  // convex hull of the peaks' kernels, CRS, counter-clockwise

  int items_nearby() const;  // distinct items of the area
};

struct ClassifiedPoint {
  db::PointXY crs;
  std::string class_name;
};

// The surveys a cell needs for a selection of `runs` runs to take part in its hotspots: two of
// them (one when there is one run).
double HotspotMinSurveys(std::size_t runs);

// `effort` (surveys per cell, the density's grid): peaks are sought only where it reaches
// min_effort_surveys; without it, everywhere.
std::vector<Hotspot> FindHotspots(const Raster& density, float nodata,
                                  std::span<const ClassifiedPoint> items,
                                  const HotspotOptions& options, const Raster* effort = nullptr);

}  // namespace littermap::heatmap

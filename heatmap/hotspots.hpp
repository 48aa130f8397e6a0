#pragma once
// Hotspots: local maxima of the density raster, at least a kernel bandwidth apart, ranked by
// density, each with the class most items within a bandwidth of it have.

#include <span>
#include <string>
#include <vector>

#include "db/geometry_blob.hpp"
#include "heatmap/raster.hpp"

namespace littermap::heatmap {

struct HotspotOptions {
  double separation_m = 3.0;           // a peak must be the maximum within this radius
  double min_density_per_100m2 = 0.0;  // and exceed this
  int max_count = 20;
};

struct Hotspot {
  int rank = 0;  // 1 = densest
  db::PointXY crs;
  double density_per_100m2 = 0.0;
  std::string dominant_class;
  int items_nearby = 0;
};

struct ClassifiedPoint {
  db::PointXY crs;
  std::string class_name;
};

std::vector<Hotspot> FindHotspots(const Raster& density, float nodata,
                                  std::span<const ClassifiedPoint> items,
                                  const HotspotOptions& options);

}  // namespace littermap::heatmap

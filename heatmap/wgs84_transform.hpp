#pragma once
// Site CRS -> WGS 84 longitude/latitude (degrees, lon first as RFC 7946 wants) through PROJ.

#include <memory>
#include <span>
#include <vector>

#include "db/geometry_blob.hpp"

namespace littermap::heatmap {

struct LonLat {
  double lon_deg = 0.0;
  double lat_deg = 0.0;
};

class Wgs84Transform {
 public:
  // Throws UsageError when PROJ has no transformation from EPSG:epsg_code.
  explicit Wgs84Transform(int epsg_code);
  ~Wgs84Transform();
  Wgs84Transform(const Wgs84Transform&) = delete;
  Wgs84Transform& operator=(const Wgs84Transform&) = delete;

  LonLat operator()(const db::PointXY& crs) const;
  // Many points in one call (PROJ's array form).
  std::vector<LonLat> operator()(std::span<const db::PointXY> crs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace littermap::heatmap

#pragma once
// Where the site map sits in its CRS: the site frame's origin at (origin_easting_m,
// origin_northing_m) and its x axis turned rotation_deg counter-clockwise from the CRS easting
// axis. A local site (no CRS) has the identity placement, so site and CRS coordinates coincide.
//   E = E0 + cos(r) x - sin(r) y,   N = N0 + sin(r) x + cos(r) y

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "db/geometry_blob.hpp"

namespace littermap::db {

struct SiteFrame {
  std::int32_t srs_id = 0;
  std::int32_t epsg_code = 0;  // 0 for a local engineering frame
  double origin_easting_m = 0.0;
  double origin_northing_m = 0.0;
  double rotation_deg = 0.0;

  bool georeferenced() const { return epsg_code != 0; }

  PointXY ToCrs(const PointXY& site) const {
    const double r = rotation_deg * std::numbers::pi / 180.0;
    return {origin_easting_m + std::cos(r) * site.x - std::sin(r) * site.y,
            origin_northing_m + std::sin(r) * site.x + std::cos(r) * site.y};
  }
  PointXY FromCrs(const PointXY& crs) const {
    const double r = rotation_deg * std::numbers::pi / 180.0;
    const double dx = crs.x - origin_easting_m;
    const double dy = crs.y - origin_northing_m;
    return {std::cos(r) * dx + std::sin(r) * dy, -std::sin(r) * dx + std::cos(r) * dy};
  }
};

// For people: "EPSG:N, origin E .. N .., rotation .. deg", or "local frame (not georeferenced)".
std::string Describe(const SiteFrame& frame);

}  // namespace littermap::db

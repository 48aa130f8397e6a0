#include "heatmap/wgs84_transform.hpp"

#include <proj.h>

#include <string>

#include "core/error.hpp"

namespace littermap::heatmap {

struct Wgs84Transform::Impl {
  PJ_CONTEXT* context = nullptr;
  PJ* transform = nullptr;
  ~Impl() {
    proj_destroy(transform);
    proj_context_destroy(context);
  }
};

Wgs84Transform::Wgs84Transform(int epsg_code) : impl_(std::make_unique<Impl>()) {
  const std::string source = "EPSG:" + std::to_string(epsg_code);
  impl_->context = proj_context_create();
  proj_log_level(impl_->context, PJ_LOG_NONE);
  PJ* raw = proj_create_crs_to_crs(impl_->context, source.c_str(), "EPSG:4326", nullptr);
  if (raw == nullptr) throw UsageError(source + ": PROJ has no transformation to WGS 84");
  // EPSG:4326 is latitude first; normalise to longitude, latitude.
  impl_->transform = proj_normalize_for_visualization(impl_->context, raw);
  proj_destroy(raw);
  if (impl_->transform == nullptr) throw UsageError(source + ": PROJ cannot normalise to lon/lat");
}

Wgs84Transform::~Wgs84Transform() = default;

LonLat Wgs84Transform::operator()(const db::PointXY& crs) const {
  const PJ_COORD out = proj_trans(impl_->transform, PJ_FWD, proj_coord(crs.x, crs.y, 0.0, 0.0));
  return {out.xy.x, out.xy.y};
}

std::vector<LonLat> Wgs84Transform::operator()(std::span<const db::PointXY> crs) const {
  static_assert(sizeof(LonLat) == 2 * sizeof(double) && sizeof(db::PointXY) == 2 * sizeof(double));
  std::vector<LonLat> lonlat(crs.size());
  for (std::size_t i = 0; i < crs.size(); ++i) lonlat[i] = {crs[i].x, crs[i].y};
  if (!lonlat.empty()) {
    constexpr std::size_t kStride = sizeof(LonLat);
    proj_trans_generic(impl_->transform, PJ_FWD, &lonlat[0].lon_deg, kStride, lonlat.size(),
                       &lonlat[0].lat_deg, kStride, lonlat.size(), nullptr, 0, 0, nullptr, 0, 0);
  }
  return lonlat;
}

}  // namespace littermap::heatmap

#pragma once
// Vector exports for web maps and spreadsheets: items.csv, items.geojson (RFC 7946: WGS 84
// longitude/latitude, no "crs" member) and hotspots.csv. Coordinates are given in the site
// frame, the site CRS and, for a georeferenced site, WGS 84.

#include <filesystem>
#include <span>
#include <vector>

#include "db/site_database.hpp"
#include "heatmap/hotspots.hpp"
#include "heatmap/wgs84_transform.hpp"

namespace littermap::heatmap {

// `wgs84` is null for a site in a local frame: the lon/lat columns stay empty.
void WriteItemsCsv(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                   const db::SiteFrame& frame, const Wgs84Transform* wgs84);

void WriteItemsGeoJson(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                       const db::SiteFrame& frame, const Wgs84Transform& wgs84);

void WriteHotspotsCsv(const std::filesystem::path& file, std::span<const Hotspot> hotspots,
                      const db::SiteFrame& frame, const Wgs84Transform* wgs84);

}  // namespace littermap::heatmap

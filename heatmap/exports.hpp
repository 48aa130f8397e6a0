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

// The items' WGS 84 positions, computed once for both item exports; none when `wgs84` is null
// (a site in a local frame).
std::vector<LonLat> ItemsLonLat(std::span<const db::ItemRecord> items, const db::SiteFrame& frame,
                                const Wgs84Transform* wgs84);

// `lonlat` holds each item's WGS 84 position (ItemsLonLat), or nothing for a site in a local
// frame: the lon/lat columns stay empty.
void WriteItemsCsv(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                   const db::SiteFrame& frame, std::span<const LonLat> lonlat);

// GeoJSON is WGS 84 only: `lonlat` must hold every item's position.
void WriteItemsGeoJson(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                       std::span<const LonLat> lonlat);

// `wgs84` is null for a site in a local frame: the lon/lat columns stay empty.
void WriteHotspotsCsv(const std::filesystem::path& file, std::span<const Hotspot> hotspots,
                      const db::SiteFrame& frame, const Wgs84Transform* wgs84);

}  // namespace littermap::heatmap

// SiteDatabase's typed access to runs, tracks and items (the schema is in site_migrations.cpp).

#include <cmath>

#include "core/error.hpp"
#include "core/time.hpp"
#include "db/site_database.hpp"

namespace littermap::db {
namespace {

double PathLength(std::span<const PointXY> points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  }
  return length;
}

}  // namespace

std::optional<std::int64_t> SiteDatabase::FindRun(const std::string& source_digest) {
  const auto query = connection_->Prepare("SELECT run_id FROM runs WHERE source_digest = ?");
  query->Bind(1, source_digest);
  if (!query->Step()) return std::nullopt;
  return query->ColumnInt64(0);
}

std::int64_t SiteDatabase::AddRun(const RunRecord& run) {
  const auto insert = connection_->Prepare(
      "INSERT INTO runs (site_id, name, source_digest, start_time_s, end_time_s, length_m, "
      "site_from_run_x_m, site_from_run_y_m, site_from_run_yaw_rad, registration_quality, "
      "reconstruction_quality) VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING run_id");
  insert->Bind(1, run.name);
  insert->Bind(2, run.source_digest);
  insert->BindReal(3, run.start_time_s);
  insert->BindReal(4, run.end_time_s);
  insert->BindReal(5, run.length_m);
  insert->BindReal(6, run.T_site_run.x_m);
  insert->BindReal(7, run.T_site_run.y_m);
  insert->BindReal(8, run.T_site_run.theta_rad);
  if (run.registration_quality) {
    insert->BindReal(9, *run.registration_quality);
  } else {
    insert->BindNull(9);
  }
  if (run.reconstruction_quality.empty()) {
    insert->BindNull(10);
  } else {
    insert->Bind(10, run.reconstruction_quality);
  }
  insert->Step();
  return insert->ColumnInt64(0);
}

std::vector<RunRecord> SiteDatabase::Runs() {
  const auto query = connection_->Prepare(
      "SELECT run_id, name, source_digest, start_time_s, end_time_s, length_m, "
      "site_from_run_x_m, site_from_run_y_m, site_from_run_yaw_rad, registration_quality, "
      "reconstruction_quality FROM runs ORDER BY run_id");
  std::vector<RunRecord> runs;
  while (query->Step()) {
    RunRecord& run = runs.emplace_back();
    run.run_id = query->ColumnInt64(0);
    run.name = query->ColumnText(1);
    run.source_digest = query->ColumnText(2);
    run.start_time_s = query->ColumnDouble(3);
    run.end_time_s = query->ColumnDouble(4);
    run.length_m = query->ColumnDouble(5);
    run.T_site_run = {query->ColumnDouble(6), query->ColumnDouble(7), query->ColumnDouble(8)};
    if (!query->ColumnIsNull(9)) run.registration_quality = query->ColumnDouble(9);
    if (!query->ColumnIsNull(10)) run.reconstruction_quality = query->ColumnText(10);
  }
  return runs;
}

bool CoverageRecord::Covers(const PointXY& crs) const {
  const double column = std::floor((crs.x - min_x_m) / cell_size_m);
  const double row = std::floor((max_y_m - crs.y) / cell_size_m);
  if (!(column >= 0 && row >= 0 && column < width && row < height)) return false;
  return observed[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(column)] != 0;
}

std::optional<std::uint8_t> SiteMapRecord::GreyAt(const PointXY& site_xy) const {
  // Into the map's frame: the inverse of T_site_map.
  const double dx = site_xy.x - T_site_map.x_m, dy = site_xy.y - T_site_map.y_m;
  const double c = std::cos(T_site_map.theta_rad), s = std::sin(T_site_map.theta_rad);
  return image.GreyAt(c * dx + s * dy, -s * dx + c * dy);
}

std::optional<SiteMapRecord> SiteDatabase::SiteMap() {
  const auto query = connection_->Prepare(
      "SELECT run_id, resolution_m, origin_x_m, origin_y_m, width, height, occupied_threshold, "
      "site_from_map_x_m, site_from_map_y_m, site_from_map_yaw_rad, pixels FROM site_map");
  if (!query->Step()) return std::nullopt;
  SiteMapRecord map;
  map.run_id = query->ColumnInt64(0);
  map.image.resolution_m = query->ColumnDouble(1);
  map.image.origin_x_m = query->ColumnDouble(2);
  map.image.origin_y_m = query->ColumnDouble(3);
  map.image.width = static_cast<int>(query->ColumnInt64(4));
  map.image.height = static_cast<int>(query->ColumnInt64(5));
  map.image.occupied_threshold = query->ColumnDouble(6);
  map.T_site_map = {query->ColumnDouble(7), query->ColumnDouble(8), query->ColumnDouble(9)};
  const std::span<const std::uint8_t> pixels = query->ColumnBlob(10);
  map.image.pixels.assign(pixels.begin(), pixels.end());
  return map;
}

void SiteDatabase::SetSiteMap(const SiteMapRecord& map) {
  if (SiteMap()) throw InternalError(name() + ": the site already has a map");
  const auto insert = connection_->Prepare(
      "INSERT INTO site_map (site_map_id, run_id, resolution_m, origin_x_m, origin_y_m, width, "
      "height, occupied_threshold, site_from_map_x_m, site_from_map_y_m, site_from_map_yaw_rad, "
      "pixels) VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert->Bind(1, map.run_id);
  insert->BindReal(2, map.image.resolution_m);
  insert->BindReal(3, map.image.origin_x_m);
  insert->BindReal(4, map.image.origin_y_m);
  insert->Bind(5, std::int64_t{map.image.width});
  insert->Bind(6, std::int64_t{map.image.height});
  insert->BindReal(7, map.image.occupied_threshold);
  insert->BindReal(8, map.T_site_map.x_m);
  insert->BindReal(9, map.T_site_map.y_m);
  insert->BindReal(10, map.T_site_map.theta_rad);
  insert->BindBlob(11, map.image.pixels);
  insert->Run();
}

void SiteDatabase::AddRunTrack(std::int64_t run_id, std::span<const PointXY> site_points) {
  const auto run = connection_->Prepare("SELECT name, start_time_s FROM runs WHERE run_id = ?");
  run->Bind(1, run_id);
  if (!run->Step()) {
    throw InternalError("run track of run " + std::to_string(run_id) +
                        ", which is not in the site");
  }
  std::vector<PointXY> crs_points;
  crs_points.reserve(site_points.size());
  for (const PointXY& p : site_points) crs_points.push_back(site_.frame.ToCrs(p));
  const std::vector<std::uint8_t> geometry = GeometryBytes(WkbType::kLineString, crs_points);
  const auto insert = connection_->Prepare(
      "INSERT INTO run_tracks (geom, run_id, pose_count, length_m, run_name, start_utc) VALUES (" +
      GeometryParameter(1) + ", ?2, ?3, ?4, ?5, ?6)");
  insert->BindBlob(1, geometry);
  insert->Bind(2, run_id);
  insert->Bind(3, static_cast<std::int64_t>(site_points.size()));
  insert->BindReal(4, PathLength(site_points));
  insert->Bind(5, run->ColumnText(0));
  if (run->ColumnIsNull(1)) {
    insert->BindNull(6);
  } else {
    insert->Bind(6, FormatUtc(run->ColumnDouble(1), "%Y-%m-%dT%H:%M:%SZ"));
  }
  insert->Run();
  ExtendLayerExtent("run_tracks", EnvelopeOf(crs_points));
}

std::vector<RunTrack> SiteDatabase::RunTracks() {
  const auto query = connection_->Prepare("SELECT fid, run_id, " + GeometryColumn("geom") +
                                          " FROM run_tracks ORDER BY run_id");
  std::vector<RunTrack> tracks;
  while (query->Step()) {
    const std::string where = name() + ": run_tracks fid " + std::to_string(query->ColumnInt64(0));
    const GeometryBlob geometry = ReadGeometry(query->ColumnBlob(2), where);
    RunTrack track{query->ColumnInt64(1), {}};
    for (const PointXY& p : geometry.points) track.site_points.push_back(site_.frame.FromCrs(p));
    tracks.push_back(std::move(track));
  }
  return tracks;
}

std::int64_t SiteDatabase::AddItem(const ItemRecord& item) {
  const PointXY crs = site_.frame.ToCrs(item.site_xy);
  const std::vector<std::uint8_t> blob = GeometryBytes(WkbType::kPoint, std::span(&crs, 1));
  const auto insert = connection_->Prepare(
      "INSERT INTO litter_items (geom, class, site_x_m, site_y_m, z_m, size_m, confidence, "
      "first_run_id, last_run_id, times_seen) VALUES (" +
      GeometryParameter(1) + ", ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10) RETURNING fid");
  insert->BindBlob(1, blob);
  insert->Bind(2, item.class_name);
  insert->BindReal(3, item.site_xy.x);
  insert->BindReal(4, item.site_xy.y);
  insert->BindReal(5, item.z_m);
  insert->BindReal(6, item.size_m);
  insert->BindReal(7, item.confidence);
  insert->Bind(8, item.first_run_id);
  insert->Bind(9, item.last_run_id);
  insert->Bind(10, std::int64_t{item.times_seen});
  insert->Step();
  const std::int64_t fid = insert->ColumnInt64(0);
  ExtendLayerExtent("litter_items", {crs.x, crs.x, crs.y, crs.y});
  return fid;
}

namespace {

constexpr const char* kItemColumns =
    "SELECT fid, class, site_x_m, site_y_m, z_m, size_m, confidence, first_run_id, last_run_id, "
    "times_seen FROM litter_items ";

std::vector<ItemRecord> ReadItems(SqlStatement& query, std::size_t expected = 0) {
  std::vector<ItemRecord> items;
  items.reserve(expected);
  while (query.Step()) {
    ItemRecord item;
    item.fid = query.ColumnInt64(0);
    item.class_name = query.ColumnText(1);
    item.site_xy = {query.ColumnDouble(2), query.ColumnDouble(3)};
    item.z_m = query.ColumnDouble(4);
    item.size_m = query.ColumnDouble(5);
    item.confidence = query.ColumnDouble(6);
    item.first_run_id = query.ColumnInt64(7);
    item.last_run_id = query.ColumnInt64(8);
    item.times_seen = static_cast<int>(query.ColumnInt64(9));
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace

std::size_t SiteDatabase::RowCount(const char* table) {
  const auto count = connection_->Prepare(std::string("SELECT count(*) FROM ") + table);
  return count->Step() ? static_cast<std::size_t>(count->ColumnInt64(0)) : 0;
}

std::vector<ItemRecord> SiteDatabase::Items() {
  const std::size_t expected = RowCount("litter_items");
  const auto query = connection_->Prepare(std::string(kItemColumns) + "ORDER BY fid");
  return ReadItems(*query, expected);
}

std::vector<ItemRecord> SiteDatabase::ItemsWithin(const Envelope& site_envelope) {
  const auto query = connection_->Prepare(
      std::string(kItemColumns) +
      "WHERE site_x_m BETWEEN ? AND ? AND site_y_m BETWEEN ? AND ? ORDER BY fid");
  query->BindReal(1, site_envelope.min_x);
  query->BindReal(2, site_envelope.max_x);
  query->BindReal(3, site_envelope.min_y);
  query->BindReal(4, site_envelope.max_y);
  return ReadItems(*query);
}

}  // namespace littermap::db

// SiteDatabase's typed access to detections, coverage and hotspots.

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "db/site_database.hpp"

namespace littermap::db {

void SiteDatabase::MarkItemSeen(std::int64_t fid, std::int64_t run_id) {
  const auto update = connection_->Prepare(
      "UPDATE litter_items SET "
      "first_run_id = CASE WHEN (SELECT start_time_s FROM runs WHERE run_id = ?1) < "
      "(SELECT start_time_s FROM runs WHERE run_id = first_run_id) THEN ?1 ELSE first_run_id END, "
      "last_run_id = CASE WHEN (SELECT start_time_s FROM runs WHERE run_id = ?1) > "
      "(SELECT start_time_s FROM runs WHERE run_id = last_run_id) THEN ?1 ELSE last_run_id END, "
      "times_seen = times_seen + 1 WHERE fid = ?2");
  update->Bind(1, run_id);
  update->Bind(2, fid);
  update->Run();
}

void SiteDatabase::AddDetection(const DetectionRecord& detection) {
  const auto insert = connection_->Prepare(
      "INSERT INTO detections (run_id, item_fid, run_item_id, class, site_x_m, site_y_m, z_m, "
      "size_m, confidence) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert->Bind(1, detection.run_id);
  if (detection.item_fid) {
    insert->Bind(2, *detection.item_fid);
  } else {
    insert->BindNull(2);
  }
  insert->Bind(3, detection.run_item_id);
  insert->Bind(4, detection.class_name);
  insert->BindReal(5, detection.site_xy.x);
  insert->BindReal(6, detection.site_xy.y);
  insert->BindReal(7, detection.z_m);
  insert->BindReal(8, detection.size_m);
  insert->BindReal(9, detection.confidence);
  insert->Run();
}

std::size_t SiteDatabase::DetectionCount(std::int64_t run_id) {
  const auto query = connection_->Prepare("SELECT count(*) FROM detections WHERE run_id = ?");
  query->Bind(1, run_id);
  return query->Step() ? static_cast<std::size_t>(query->ColumnInt64(0)) : 0;
}

namespace {

constexpr const char* kDetectionColumns =
    "SELECT run_id, item_fid, run_item_id, class, site_x_m, site_y_m, z_m, size_m, confidence "
    "FROM detections ";

DetectionRecord ReadDetection(const SqlStatement& query) {
  DetectionRecord detection;
  detection.run_id = query.ColumnInt64(0);
  if (!query.ColumnIsNull(1)) detection.item_fid = query.ColumnInt64(1);
  detection.run_item_id = query.ColumnText(2);
  detection.class_name = query.ColumnText(3);
  detection.site_xy = {query.ColumnDouble(4), query.ColumnDouble(5)};
  detection.z_m = query.ColumnDouble(6);
  detection.size_m = query.ColumnDouble(7);
  detection.confidence = query.ColumnDouble(8);
  return detection;
}

}  // namespace

std::vector<DetectionRecord> SiteDatabase::Detections(const std::vector<std::int64_t>& run_ids) {
  const auto query = connection_->Prepare(std::string(kDetectionColumns) +
                                          "WHERE run_id = ? ORDER BY detection_id");
  std::vector<DetectionRecord> detections;
  for (std::int64_t run_id : run_ids) {
    query->Bind(1, run_id);
    while (query->Step()) detections.push_back(ReadDetection(*query));
    query->Reset();
  }
  return detections;
}

std::vector<DetectionRecord> SiteDatabase::AllDetections() {
  // In the order stored, then by run: no sort of the whole table in the database, and none
  // here when each run's detections were stored together (a run is ingested in one transaction).
  std::vector<DetectionRecord> detections;
  detections.reserve(RowCount("detections"));
  const auto query = connection_->Prepare(std::string(kDetectionColumns) + "ORDER BY detection_id");
  while (query->Step()) detections.push_back(ReadDetection(*query));
  const auto by_run = [](const auto& a, const auto& b) { return a.run_id < b.run_id; };
  if (!std::is_sorted(detections.begin(), detections.end(), by_run)) {
    std::stable_sort(detections.begin(), detections.end(), by_run);
  }
  return detections;
}

void SiteDatabase::AddCoverage(const CoverageRecord& coverage) {
  if (coverage.observed.size() != static_cast<std::size_t>(coverage.width) * coverage.height) {
    throw UsageError("coverage of run " + std::to_string(coverage.run_id) +
                     ": mask size does not match width x height");
  }
  const auto insert = connection_->Prepare(
      "INSERT INTO coverage (run_id, cell_size_m, origin_x_m, origin_y_m, width, height, "
      "observed_area_m2, encoding, data) VALUES (?, ?, ?, ?, ?, ?, ?, 'u8-rowmajor-nw', ?)");
  insert->Bind(1, coverage.run_id);
  insert->BindReal(2, coverage.cell_size_m);
  insert->BindReal(3, coverage.min_x_m);
  insert->BindReal(4, coverage.max_y_m);
  insert->Bind(5, std::int64_t{coverage.width});
  insert->Bind(6, std::int64_t{coverage.height});
  insert->BindReal(7, coverage.observed_area_m2);
  insert->BindBlob(8, coverage.observed);
  insert->Run();
}

std::vector<CoverageRecord> SiteDatabase::Coverages() {
  const auto query = connection_->Prepare(
      "SELECT run_id, cell_size_m, origin_x_m, origin_y_m, width, height, observed_area_m2, "
      "encoding, data FROM coverage ORDER BY run_id");
  std::vector<CoverageRecord> coverages;
  while (query->Step()) {
    CoverageRecord coverage;
    coverage.run_id = query->ColumnInt64(0);
    coverage.cell_size_m = query->ColumnDouble(1);
    coverage.min_x_m = query->ColumnDouble(2);
    coverage.max_y_m = query->ColumnDouble(3);
    coverage.width = static_cast<int>(query->ColumnInt64(4));
    coverage.height = static_cast<int>(query->ColumnInt64(5));
    coverage.observed_area_m2 = query->ColumnDouble(6);
    const auto blob = query->ColumnBlob(8);
    const std::string where = name() + ": coverage of run " + std::to_string(coverage.run_id);
    if (query->ColumnText(7) != "u8-rowmajor-nw") throw BadInputError(where + ": unknown encoding");
    if (blob.size() != static_cast<std::size_t>(coverage.width) * coverage.height) {
      throw BadInputError(where + ": mask size does not match width x height");
    }
    coverage.observed.assign(blob.begin(), blob.end());
    coverages.push_back(std::move(coverage));
  }
  return coverages;
}

void SiteDatabase::ReplaceHotspots(const HotspotFilter& filter,
                                   const std::vector<HotspotRecord>& hotspots) {
  const auto remove = connection_->Prepare(
      "DELETE FROM hotspots WHERE filter_class = ? AND filter_from_utc = ? AND filter_to_utc = ? "
      "AND filter_min_confidence = ?");
  remove->Bind(1, filter.class_name);
  remove->Bind(2, filter.from_utc);
  remove->Bind(3, filter.to_utc);
  remove->Bind(4, filter.min_confidence);
  remove->Run();
  const auto insert = connection_->Prepare(
      "INSERT INTO hotspots (geom, rank, site_x_m, site_y_m, density_per_100m2, dominant_class, "
      "filter_class, filter_from_utc, filter_to_utc, filter_min_confidence) VALUES (" +
      GeometryParameter(1) + ", ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  for (const HotspotRecord& hotspot : hotspots) {
    const PointXY crs = site_.frame.ToCrs(hotspot.site_xy);
    const std::vector<std::uint8_t> blob = GeometryBytes(WkbType::kPoint, std::span(&crs, 1));
    insert->BindBlob(1, blob);
    insert->Bind(2, std::int64_t{hotspot.rank});
    insert->BindReal(3, hotspot.site_xy.x);
    insert->BindReal(4, hotspot.site_xy.y);
    insert->BindReal(5, hotspot.density_per_100m2);
    if (hotspot.dominant_class.empty()) {
      insert->BindNull(6);
    } else {
      insert->Bind(6, hotspot.dominant_class);
    }
    insert->Bind(7, filter.class_name);
    insert->Bind(8, filter.from_utc);
    insert->Bind(9, filter.to_utc);
    insert->Bind(10, filter.min_confidence);
    insert->Run();
  }
  // The layer's extent: of every set it holds now.
  if (engine() != SqlEngine::kSqlite) return;
  connection_->Execute(
      "UPDATE gpkg_contents SET min_x = NULL, min_y = NULL, max_x = NULL, max_y = NULL "
      "WHERE table_name = 'hotspots'");
  const auto rows = connection_->Prepare("SELECT site_x_m, site_y_m FROM hotspots");
  while (rows->Step()) {
    const PointXY crs = site_.frame.ToCrs({rows->ColumnDouble(0), rows->ColumnDouble(1)});
    ExtendLayerExtent("hotspots", {crs.x, crs.x, crs.y, crs.y});
  }
}

}  // namespace littermap::db

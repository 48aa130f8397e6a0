#pragma once
// One site's database, in either of two engines (site_locator.hpp):
// - an SQLite file that is also an OGC GeoPackage 1.3 (QGIS opens it as it is), with foreign
//   keys on, WAL journaling and a busy timeout, so two processes may write one site (one waits
//   for the other's transaction);
// - a schema of a PostgreSQL database with PostGIS, for many robots and machines writing one
//   city's parks: writers of a site queue on its advisory lock; QGIS and GDAL read the layers.
// Feature tables litter_items, hotspots (POINT) and run_tracks (LINESTRING) hold geometry in the
// site CRS (a PostGIS site in a local frame has SRID 0); the tables sites, runs, detections,
// coverage and site_map are littermap's own. Both engines have the same tables and columns
// (site_schema.hpp) and run the same statements.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/occupancy_image.hpp"
#include "core/planar_pose.hpp"
#include "core/sqlite_database.hpp"
#include "db/geometry_blob.hpp"
#include "db/site_frame.hpp"
#include "db/site_locator.hpp"
#include "db/sql_connection.hpp"

namespace littermap::db {

struct SiteOptions {
  std::string name;
  std::optional<int> epsg_code;  // none: a local engineering frame
  double origin_easting_m = 0.0;
  double origin_northing_m = 0.0;
  double rotation_deg = 0.0;
};

struct SiteInfo {
  std::string name;
  SiteFrame frame;
  std::string created_utc;
  int schema_version = 0;
};

struct RunRecord {
  std::int64_t run_id = 0;
  std::string name;
  std::string source_digest;  // identifies the run's inputs: ingesting it twice is a no-op
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  double length_m = 0.0;
  PlanarPose T_site_run;                       // the run's map frame in the site frame
  std::optional<double> registration_quality;  // matching ratio; none: not matched (first run,
                                               // manual transform, or no map)
  std::string reconstruction_quality;  // reconstruct's quality.json (JSON text); empty: unknown
};

// The occupancy map later runs are registered onto (reconstruct's map.pgm of the first run).
struct SiteMapRecord {
  std::int64_t run_id = 0;
  OccupancyImage image;  // in the frame of the run that defined it
  PlanarPose T_site_map;

  // The grey level of the cell under a point of the site frame; none outside the map.
  std::optional<std::uint8_t> GreyAt(const PointXY& site_xy) const;
};

struct ItemRecord {
  std::int64_t fid = 0;
  std::string class_name;
  PointXY site_xy;  // site frame, metres
  double z_m = 0.0;
  double size_m = 0.0;
  double confidence = 1.0;
  std::int64_t first_run_id = 0;
  std::int64_t last_run_id = 0;
  int times_seen = 1;
};

struct DetectionRecord {
  std::int64_t run_id = 0;
  std::optional<std::int64_t> item_fid;
  std::string run_item_id;  // the item's id within its run (items.csv "id")
  std::string class_name;
  PointXY site_xy;
  double z_m = 0.0;
  double size_m = 0.0;
  double confidence = 1.0;
};

// Which ground cells one run's camera observed, on a north-up grid in the site CRS.
struct CoverageRecord {
  std::int64_t run_id = 0;
  double cell_size_m = 0.0;
  double min_x_m = 0.0;  // western edge, site CRS
  double max_y_m = 0.0;  // northern edge, site CRS
  int width = 0;
  int height = 0;
  double observed_area_m2 = 0.0;
  std::vector<std::uint8_t> observed;  // row-major, 1 = observed

  // Whether the run observed the ground at a point of the site CRS.
  bool Covers(const PointXY& crs) const;
};

// Which items a set of hotspots was computed from ('' for any class, date or period).
struct HotspotFilter {
  std::string class_name;
  std::string from_utc;        // runs starting on or after, YYYY-MM-DDTHH:MM:SSZ
  std::string to_utc;          // runs starting before
  std::string min_confidence;  // detections at least this sure, as given ("" for all)
};

struct HotspotRecord {
  int rank = 0;
  PointXY site_xy;
  double density_per_100m2 = 0.0;
  std::string dominant_class;
};

struct RunTrack {
  std::int64_t run_id = 0;
  std::vector<PointXY> site_points;  // site frame, metres
};

class SiteDatabase {
 public:
  // Throws UsageError when the site exists or the CRS is unusable; leaves nothing behind (no
  // file; no schema).
  static SiteDatabase Create(const SiteLocator& where, const SiteOptions& options);
  // Throws BadInputError naming the site when it is not a littermap site; applies pending
  // schema migrations.
  static SiteDatabase Open(const SiteLocator& where);
  // For the commands that only read (report): a GeoPackage is opened read-only, so a site one
  // may only read (a share, a copy with mode 0444) is enough. A site that needs a schema
  // migration is a BadInputError saying that a writing command upgrades it.
  static SiteDatabase OpenReadOnly(const SiteLocator& where);
  // Whether something is there to open: the file, or the schema's sites table. Throws
  // PostgresError when the server cannot be reached.
  static bool Exists(const SiteLocator& where);

  SiteDatabase(SiteDatabase&&) noexcept;
  SiteDatabase& operator=(SiteDatabase&&) = delete;
  ~SiteDatabase();

  const SiteInfo& site() const { return site_; }
  SqlEngine engine() const { return connection_->engine(); }
  // For messages: the file, or the database and site.
  const std::string& name() const { return connection_->name(); }
  SqlConnection& sql() { return *connection_; }
  // The GeoPackage's SQLite database; throws InternalError for a PostGIS site.
  SqliteDatabase& sqlite();

  // One writer at a time (SQLite's BEGIN IMMEDIATE; the site's advisory lock in PostgreSQL);
  // commits, or rolls back when `body` throws. A transaction the engine aborts because a
  // concurrent one conflicted with it is run again, after a random pause, up to kWriteAttempts
  // times: `body` must start from scratch each time it is called.
  template <typename Body>
  void InTransaction(Body&& body) {
    for (int attempt = 1;; ++attempt) {
      connection_->BeginWrite();
      try {
        body();
        connection_->Commit();
        return;
      } catch (const std::exception& error) {
        RollbackQuietly();
        if (!connection_->IsConflict(error) || attempt == kWriteAttempts) throw;
      } catch (...) {
        RollbackQuietly();
        throw;
      }
      ++conflicts_retried_;
      PauseAfterConflict(attempt);
    }
  }
  static constexpr int kWriteAttempts = 20;
  // Transactions this connection ran again after a conflict.
  std::size_t conflicts_retried() const { return conflicts_retried_; }

  std::optional<std::int64_t> FindRun(const std::string& source_digest);
  std::int64_t AddRun(const RunRecord& run);
  std::vector<RunRecord> Runs();
  std::optional<SiteMapRecord> SiteMap();
  // Throws InternalError if the site already has a map.
  void SetSiteMap(const SiteMapRecord& map);
  void AddRunTrack(std::int64_t run_id, std::span<const PointXY> site_points);
  std::vector<RunTrack> RunTracks();
  std::int64_t AddItem(const ItemRecord& item);
  std::vector<ItemRecord> Items();
  // The items whose site-frame position lies in the envelope (an index serves it).
  std::vector<ItemRecord> ItemsWithin(const Envelope& site_envelope);
  // The item was seen again by run_id: times_seen counts it, and first_run_id / last_run_id
  // become run_id when it started before the first / after the last run that saw the item, so
  // they mean the earliest and latest survey whatever order the runs were ingested in.
  void MarkItemSeen(std::int64_t fid, std::int64_t run_id);
  void AddDetection(const DetectionRecord& detection);
  std::size_t DetectionCount(std::int64_t run_id);
  // The detections of these runs, in run order.
  std::vector<DetectionRecord> Detections(const std::vector<std::int64_t>& run_ids);
  // Every detection, by run id, each run's in the order stored.
  std::vector<DetectionRecord> AllDetections();
  void AddCoverage(const CoverageRecord& coverage);
  std::vector<CoverageRecord> Coverages();
  // Replaces the hotspots computed with this filter (recomputed from the runs each time); the
  // sets of other filters stay.
  void ReplaceHotspots(const HotspotFilter& filter, const std::vector<HotspotRecord>& hotspots);

  // Removes the site: the file (and its WAL), or the schema with everything in it. Nothing there
  // is no error.
  static void Remove(const SiteLocator& where);

  // Where the engines differ, for code that reads and writes the tables column by column
  // (site_copy.cpp): how a geometry parameter is written and a geometry column read (a
  // GeoPackage blob; WKB through PostGIS), and the GeoPackage's layer extents.
  std::string GeometryParameter(int index) const;
  std::string GeometryColumn(const char* column) const;
  std::vector<std::uint8_t> GeometryBytes(WkbType type, std::span<const PointXY> crs_points) const;
  GeometryBlob ReadGeometry(std::span<const std::uint8_t> bytes, const std::string& where) const;
  void ExtendLayerExtent(const std::string& table, const Envelope& crs_envelope);

 private:
  explicit SiteDatabase(std::unique_ptr<SqlConnection> connection);
  static SiteDatabase CreateGeoPackage(const std::filesystem::path& file,
                                       const SiteOptions& options);
  static SiteDatabase CreatePostgres(const SiteLocator& where, const SiteOptions& options);
  static SiteDatabase OpenGeoPackage(const std::filesystem::path& file, bool read_only);
  static SiteDatabase OpenPostgres(const SiteLocator& where, bool read_only);
  void ConfigureGeoPackage();
  void LoadSite();
  void RollbackQuietly() noexcept;
  static void PauseAfterConflict(int attempt);
  // The rows of a table: what a whole-table read reserves, so a city park's million rows are not
  // moved about as the vector grows.
  std::size_t RowCount(const char* table);

  std::unique_ptr<SqlConnection> connection_;
  SiteInfo site_;
  std::size_t conflicts_retried_ = 0;
};

}  // namespace littermap::db

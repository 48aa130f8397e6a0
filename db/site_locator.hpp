#pragma once
// Where a site lives, as the user wrote it: a GeoPackage file, or a PostgreSQL database and the
// schema that holds the site.
//   park.gpkg
//   postgresql:///city?site=north_park
//   postgresql://user@host:5432/city?options=-csearch_path%3Dnorth_park
// One site is one schema: its tables keep the GeoPackage's names and meanings, QGIS lists each
// park as its own group of layers, and removing or copying a park is one schema's business.

#include <filesystem>
#include <string>

namespace littermap::db {

struct SiteLocator {
  std::filesystem::path file;  // a GeoPackage (empty for PostgreSQL)
  std::string conninfo;        // libpq's URI, without littermap's site= parameter
  std::string schema;          // the site's schema
  std::string display;         // for messages: the path, or the URI without a password

  SiteLocator() = default;
  SiteLocator(const std::filesystem::path& gpkg)  // NOLINT: a path is a GeoPackage site
      : file(gpkg), display(gpkg.string()) {}

  bool postgres() const { return !conninfo.empty(); }
};

// True for postgresql:// and postgres:// URIs.
bool IsPostgresUri(const std::string& text);

// A path, or a PostgreSQL URI naming its site by ?site=NAME or by a search_path in ?options=.
// Throws UsageError naming `what` when a URI names no site or a site name that is not a plain
// lower-case SQL identifier (letters, digits, _; at most 63 bytes).
SiteLocator ParseSiteLocator(const std::string& text, const std::string& what = "SITE");

}  // namespace littermap::db

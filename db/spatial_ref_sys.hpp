#pragma once
// Rows of gpkg_spatial_ref_sys: the three every GeoPackage must hold (clause 1.1.2.1.2), the
// site CRS from the EPSG registry (definition text from PROJ), or a local engineering frame for
// a site without georeference.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace littermap::db {

struct SpatialRefSys {
  std::string srs_name;
  std::int32_t srs_id = 0;
  std::string organization;
  std::int32_t organization_coordsys_id = 0;
  std::string definition;  // WKT 1 (the GeoPackage core definition column)
  std::string description;
};

// srs_id of the local site frame (GeoPackage leaves ids outside the EPSG range to the user).
constexpr std::int32_t kLocalSiteSrsId = 100000;

// WGS 84 (4326), undefined cartesian (-1) and undefined geographic (0).
std::vector<SpatialRefSys> RequiredSpatialRefSys();

// The EPSG code of a CRS as people write it: "EPSG:32633", "epsg:32633" or "32633"; none for an
// empty text. Throws UsageError naming `what` (the option that gave it) for any other text.
std::optional<int> ParseEpsgCode(const std::string& text, const std::string& what);

// A projected CRS in metres from the EPSG registry; throws UsageError naming the code when PROJ
// does not know it or it is not a projected CRS with metre axes (site coordinates are metres).
SpatialRefSys EpsgSpatialRefSys(int epsg_code);

// Throws UsageError with the CRS's area of use when the site origin (metres in that CRS) is not
// finite or does not lie in that area widened by kOriginMarginDeg (a site a little beyond a UTM
// zone's edge is still mapped well; one 1,000 km off is a typing error).
constexpr double kOriginMarginDeg = 5.0;
void CheckSiteOrigin(int epsg_code, double easting_m, double northing_m);

// A right-handed metric frame (x east, y north) with no link to the Earth.
SpatialRefSys LocalSpatialRefSys(const std::string& site_name);

// The one name of a site's local engineering CRS, in the GeoPackage (srs_name and its WKT) and
// in the GeoTIFFs, so that a GIS shows the layers and rasters in one CRS.
std::string LocalCrsName(const std::string& site_name);

}  // namespace littermap::db

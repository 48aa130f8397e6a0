#include "db/spatial_ref_sys.hpp"

#include <proj.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.hpp"

namespace littermap::db {
namespace {

// The WKT of EPSG:4326 as given in the GeoPackage specification (Table 11).
constexpr const char* kWgs84Wkt =
    "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,298.257223563,"
    "AUTHORITY[\"EPSG\",\"7030\"]],AUTHORITY[\"EPSG\",\"6326\"]],PRIMEM[\"Greenwich\",0,"
    "AUTHORITY[\"EPSG\",\"8901\"]],UNIT[\"degree\",0.0174532925199433,"
    "AUTHORITY[\"EPSG\",\"9122\"]],AXIS[\"Latitude\",NORTH],AXIS[\"Longitude\",EAST],"
    "AUTHORITY[\"EPSG\",\"4326\"]]";

struct ContextDeleter {
  void operator()(PJ_CONTEXT* context) const { proj_context_destroy(context); }
};
struct PjDeleter {
  void operator()(PJ* pj) const { proj_destroy(pj); }
};
using ContextPtr = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using PjPtr = std::unique_ptr<PJ, PjDeleter>;

// A CRS from PROJ's registry with its context (destroyed after it); crs is null when PROJ does
// not know the code. PROJ's own log is off: libraries never print, the errors say it all.
struct Crs {
  ContextPtr context;
  PjPtr crs;
};

Crs CreateCrs(const std::string& code) {
  Crs result{ContextPtr(proj_context_create()), nullptr};
  proj_log_level(result.context.get(), PJ_LOG_NONE);
  result.crs.reset(proj_create(result.context.get(), code.c_str()));
  return result;
}

std::string Decimal(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

bool AxesInMetres(PJ_CONTEXT* context, PJ* crs) {
  PjPtr cs(proj_crs_get_coordinate_system(context, crs));
  if (!cs) return false;
  const int axes = proj_cs_get_axis_count(context, cs.get());
  for (int i = 0; i < axes; ++i) {
    double factor = 0.0;
    if (!proj_cs_get_axis_info(context, cs.get(), i, nullptr, nullptr, nullptr, &factor, nullptr,
                               nullptr, nullptr) ||
        std::abs(factor - 1.0) > 1e-12) {
      return false;
    }
  }
  return axes >= 2;
}

}  // namespace

std::vector<SpatialRefSys> RequiredSpatialRefSys() {
  return {
      {"WGS 84 geodetic", 4326, "EPSG", 4326, kWgs84Wkt,
       "longitude/latitude coordinates in decimal degrees on the WGS 84 spheroid"},
      {"Undefined cartesian SRS", -1, "NONE", -1, "undefined",
       "undefined cartesian coordinate reference system"},
      {"Undefined geographic SRS", 0, "NONE", 0, "undefined",
       "undefined geographic coordinate reference system"},
  };
}

std::optional<int> ParseEpsgCode(const std::string& text, const std::string& what) {
  if (text.empty()) return std::nullopt;
  std::string digits = text;
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper.rfind("EPSG:", 0) == 0) digits = text.substr(5);
  const bool numeric = !digits.empty() && digits.size() < 10 &&
                       std::all_of(digits.begin(), digits.end(),
                                   [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!numeric) throw UsageError(what + " " + text + ": expected EPSG:N, e.g. EPSG:32633");
  return std::stoi(digits);
}

SpatialRefSys EpsgSpatialRefSys(int epsg_code) {
  const std::string code = "EPSG:" + std::to_string(epsg_code);
  const auto [context, crs] = CreateCrs(code);
  if (!crs) throw UsageError("--crs " + code + ": not a coordinate reference system PROJ knows");
  if (proj_get_type(crs.get()) != PJ_TYPE_PROJECTED_CRS ||
      !AxesInMetres(context.get(), crs.get())) {
    throw UsageError("--crs " + code + " (" + proj_get_name(crs.get()) +
                     "): the site CRS must be a projected CRS in metres (e.g. a UTM zone)");
  }
  const char* wkt = proj_as_wkt(context.get(), crs.get(), PJ_WKT1_GDAL, nullptr);
  if (wkt == nullptr) throw InternalError(code + ": PROJ cannot write it as WKT 1");
  SpatialRefSys srs;
  srs.srs_name = proj_get_name(crs.get());
  srs.srs_id = epsg_code;
  srs.organization = "EPSG";
  srs.organization_coordsys_id = epsg_code;
  srs.definition = wkt;
  if (const char* scope = proj_get_scope(crs.get())) srs.description = scope;
  return srs;
}

void CheckSiteOrigin(int epsg_code, double easting_m, double northing_m) {
  const std::string code = "EPSG:" + std::to_string(epsg_code);
  const std::string origin = "--origin " + Decimal(easting_m) + " " + Decimal(northing_m);
  if (!std::isfinite(easting_m) || !std::isfinite(northing_m)) {
    throw UsageError(origin + ": easting and northing must be finite numbers of metres in " + code);
  }
  const auto [context, crs] = CreateCrs(code);
  double west = 0, south = 0, east = 0, north = 0;
  const char* area = nullptr;
  if (!crs ||
      !proj_get_area_of_use(context.get(), crs.get(), &west, &south, &east, &north, &area) ||
      west < -180.0) {
    return;  // no area of use to hold the origin to
  }
  PjPtr raw(proj_create_crs_to_crs(context.get(), code.c_str(), "EPSG:4326", nullptr));
  PjPtr to_lon_lat(raw ? proj_normalize_for_visualization(context.get(), raw.get()) : nullptr);
  if (!to_lon_lat) return;
  const PJ_COORD lon_lat =
      proj_trans(to_lon_lat.get(), PJ_FWD, proj_coord(easting_m, northing_m, 0.0, 0.0));
  const double lon = lon_lat.lp.lam, lat = lon_lat.lp.phi;
  const bool lon_inside = west > east  // an area across the antimeridian: any longitude
                              ? true
                              : lon >= west - kOriginMarginDeg && lon <= east + kOriginMarginDeg;
  if (!std::isfinite(lon) || !std::isfinite(lat) || !lon_inside || lat < south - kOriginMarginDeg ||
      lat > north + kOriginMarginDeg) {
    throw UsageError(origin + ": outside the area " + code + " is made for (" + (area ? area : "") +
                     ": longitude " + Decimal(west) + " to " + Decimal(east) + ", latitude " +
                     Decimal(south) + " to " + Decimal(north) +
                     " degrees); easting and northing are metres in " + code);
  }
}

std::string LocalCrsName(const std::string& site_name) {
  return "littermap site frame: " + site_name;
}

SpatialRefSys LocalSpatialRefSys(const std::string& site_name) {
  SpatialRefSys srs;
  srs.srs_name = LocalCrsName(site_name);
  srs.srs_id = kLocalSiteSrsId;
  srs.organization = "littermap";
  srs.organization_coordsys_id = kLocalSiteSrsId;
  std::string wkt_name;  // WKT doubles a quote inside a name
  for (const char c : srs.srs_name) wkt_name += c == '"' ? std::string("\"\"") : std::string(1, c);
  srs.definition = "LOCAL_CS[\"" + wkt_name +
                   "\",LOCAL_DATUM[\"robot site map\",0],"
                   "UNIT[\"metre\",1,AUTHORITY[\"EPSG\",\"9001\"]],AXIS[\"Easting\",EAST],"
                   "AXIS[\"Northing\",NORTH]]";
  srs.description = "local engineering frame of the robot's site map, metres, not georeferenced";
  return srs;
}

}  // namespace littermap::db
